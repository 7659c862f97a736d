#include "core/mosaic/mosaic_report.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace pf::mosaic {

namespace {

std::string fmt(const char* format, double v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

std::string lonLat(const geo::LonLat& p) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "%.6f %c %.6f %c", std::abs(p.lat), p.lat >= 0 ? 'N' : 'S',
                  std::abs(p.lon), p.lon >= 0 ? 'E' : 'W');
    return buf;
}

} // namespace

std::string formatReport(const MosaicReport& r) {
    std::ostringstream out;
    using Kind = PhotoFinding::Kind;
    int leftOut = 0, unused = 0;
    for (const auto& f : r.findings) {
        if (f.excluded)
            ++leftOut;
        else if (f.kind == Kind::Unused)
            ++unused;
    }
    out << "mosaic: " << r.photosUsed << " of " << r.photosGiven << " photos used";
    if (leftOut)
        out << ", " << leftOut << " left out";
    if (unused)
        out << ", " << unused << " not needed";
    out << "\n  output:  " << r.outputPath << " (" << r.crsName << ", " << fmt("%.1f", r.gsdM * 100)
        << " cm/px, " << r.widthPx << " x " << r.heightPx << " px)\n"
        << "  vectors: " << r.vectorPath
        << " (footprints, seams, gaps, camera_positions, missing_photos)\n";

    auto list = [&](const char* title, auto pick) {
        bool any = false;
        for (const auto& f : r.findings) {
            if (!pick(f))
                continue;
            if (!any)
                out << title << '\n';
            any = true;
            out << "  " << (f.file.empty() ? std::string("(set)") : f.file) << ": " << f.message
                << '\n';
        }
    };
    list("Left out:", [](const PhotoFinding& f) { return f.excluded; });
    list("Not matching the plan:", [](const PhotoFinding& f) {
        return !f.excluded && (f.kind == Kind::FarFromPlan || f.kind == Kind::Duplicate);
    });
    if (!r.missing.empty()) {
        out << "Missing: " << r.missing.size() << " planned photo point(s) without a photo";
        if (r.missing.size() <= 10) {
            out << ":\n";
            for (const auto& m : r.missing)
                out << "  " << m.label << " at " << lonLat(m.position) << '\n';
        } else {
            // Runs of consecutive points ("Falcon 8 #13-#40"); every point is in the vectors.
            out << " (positions in the vectors' missing_photos layer):\n ";
            std::size_t i = 0;
            while (i < r.missing.size()) {
                std::size_t j = i;
                while (j + 1 < r.missing.size() &&
                       r.missing[j + 1].aircraft == r.missing[i].aircraft &&
                       r.missing[j + 1].seq == r.missing[j].seq + 1)
                    ++j;
                out << (i ? ", " : " ") << r.missing[i].label;
                if (j > i)
                    out << "-#" << r.missing[j].seq;
                i = j + 1;
            }
            out << '\n';
        }
    }
    if (r.areaM2 > 0) {
        out << "Coverage of the planned area: " << fmt("%.2f", r.coveredRatio * 100) << " % of "
            << fmt("%.0f", r.areaM2) << " m²";
        if (r.gaps.empty()) {
            out << ", no gap\n";
        } else {
            out << "; " << r.gaps.size() << " gap(s), " << fmt("%.1f", r.gapAreaM2)
                << " m² in total:\n";
            for (std::size_t i = 0; i < r.gaps.size() && i < 20; ++i)
                out << "  gap " << i + 1 << ": " << fmt("%.1f", r.gaps[i].areaM2) << " m² around "
                    << lonLat(r.gaps[i].centre) << '\n';
            if (r.gaps.size() > 20)
                out << "  ... (every gap is in the vectors' gaps layer)\n";
        }
    }
    if (!r.notes.empty()) {
        out << "Notes:\n";
        for (const auto& n : r.notes)
            out << "  " << n << '\n';
    }
    out << "done in " << fmt("%.1f", r.seconds) << " s";
    for (std::size_t i = 0; i < r.stages.size(); ++i)
        out << (i ? ", " : " (") << r.stages[i].name << ' ' << fmt("%.1f", r.stages[i].seconds)
            << (i + 1 == r.stages.size() ? ")" : "");
    out << '\n';
    return out.str();
}

} // namespace pf::mosaic
