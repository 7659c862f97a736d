#include "core/job_scope.h"

#include <algorithm>

namespace pf {

namespace {
thread_local JobScope* t_scope = nullptr;
} // namespace

JobScope::JobScope(Progress* progress, double lo, double hi, std::string prefix)
    : m_progress(progress), m_lo(lo), m_hi(hi), m_prefix(std::move(prefix)), m_outer(t_scope) {
    t_scope = this;
}

JobScope::JobScope(Progress* progress, CancelOnly) : JobScope(progress) { m_silent = true; }

JobScope::JobScope(double lo, double hi, const std::string& prefix) : m_outer(t_scope) {
    const JobScope* o = m_outer;
    m_progress = o ? o->m_progress : nullptr;
    const double olo = o ? o->m_lo : 0.0, ohi = o ? o->m_hi : 1.0;
    m_lo = olo + (ohi - olo) * lo;
    m_hi = olo + (ohi - olo) * hi;
    m_prefix = (o ? o->m_prefix : std::string()) + prefix;
    m_silent = o && o->m_silent;
    t_scope = this;
}

JobScope::Share JobScope::share() {
    const JobScope* s = t_scope;
    if (!s)
        return {};
    return {s->m_progress, s->m_lo, s->m_hi, s->m_prefix, s->m_silent};
}

JobScope::JobScope(const Share& share)
    : m_progress(share.progress), m_lo(share.lo), m_hi(share.hi), m_prefix(share.prefix),
      m_silent(share.silent), m_outer(t_scope) {
    t_scope = this;
}

JobScope::~JobScope() { t_scope = m_outer; }

Progress* JobScope::current() { return t_scope ? t_scope->m_progress : nullptr; }

bool stopRequested() {
    const Progress* p = JobScope::current();
    return p && p->cancelled();
}

void reportProgress(double fraction, const std::string& stage) {
    const JobScope* s = t_scope;
    if (s)
        s->report(fraction, stage);
}

void JobScope::report(double fraction, const std::string& stage) const {
    if (m_progress && !m_silent)
        m_progress->report(m_lo + (m_hi - m_lo) * std::clamp(fraction, 0.0, 1.0), m_prefix + stage);
}

} // namespace pf
