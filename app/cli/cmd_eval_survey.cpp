// photoflight-cli eval --survey / --generate: every planner beside the lawnmower on any number of areas,
// and the seeded generator of test areas.
#include "app/cli/args.h"
#include "app/cli/eval_survey.h"
#include "app/cli/mission_args.h"
#include "app/cli/survey_charts.h"

#include "core/mission/survey_comparison.h"
#include "core/mission/planner_kinds.h"
#include "core/mission/validation.h"
#include "core/plan/area_generator.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace pf::cli {

namespace {

std::vector<std::string> splitList(const std::string& s) {
    std::vector<std::string> out;
    std::stringstream ss(s);
    std::string item;
    while (std::getline(ss, item, ','))
        if (!item.empty())
            out.push_back(item);
    return out;
}

// "N" or "MIN-MAX" (numbers), for --zones and --size-km2.
Result<std::pair<double, double>> parseRange(const std::string& text, const std::string& flag) {
    const auto dash = text.find('-', 1);
    auto number = [&](const std::string& t, double* v) {
        char* end = nullptr;
        *v = std::strtod(t.c_str(), &end);
        return !t.empty() && end == t.c_str() + t.size() && std::isfinite(*v);
    };
    double lo = 0, hi = 0;
    const bool ok = dash == std::string::npos ? number(text, &lo) && number(text, &hi)
                                              : number(text.substr(0, dash), &lo) && number(text.substr(dash + 1), &hi);
    if (!ok)
        return makeError(ErrorCode::InvalidInput, "--" + flag + ": '" + text + "' is neither N nor MIN-MAX");
    if (lo > hi)
        return makeError(ErrorCode::InvalidInput, "--" + flag + ": the smallest value comes first (got " + text + ")");
    return std::make_pair(lo, hi);
}

Result<plan::AreaGeneratorOptions> generatorOptions(const Args& args) {
    plan::AreaGeneratorOptions o;
    auto n = args.number("generate");
    if (!n)
        return n.error();
    if (!*n || **n < 1 || **n > 100000 || std::floor(**n) != **n)
        return makeError(ErrorCode::InvalidInput, "--generate: give the number of areas, a whole number from 1 to 100000");
    o.count = static_cast<int>(**n);
    if (auto s = args.value("seed")) {
        char* end = nullptr;
        const unsigned long long v = std::strtoull(s->c_str(), &end, 10);
        if (s->empty() || end != s->c_str() + s->size() || (*s)[0] == '-')
            return makeError(ErrorCode::InvalidInput, "--seed: '" + *s + "' is not a whole number of 0 or more");
        o.seed = v;
    }
    if (auto z = args.value("zones")) {
        auto r = parseRange(*z, "zones");
        if (!r)
            return r.error();
        if (r->first < 0 || r->second > 200 || std::floor(r->first) != r->first || std::floor(r->second) != r->second)
            return makeError(ErrorCode::InvalidInput, "--zones: whole numbers from 0 to 200 (got " + *z + ")");
        o.minZones = static_cast<int>(r->first);
        o.maxZones = static_cast<int>(r->second);
    }
    if (auto s = args.value("size-km2")) {
        auto r = parseRange(*s, "size-km2");
        if (!r)
            return r.error();
        if (r->first < 0.001 || r->second > 100)
            return makeError(ErrorCode::InvalidInput, "--size-km2: sizes from 0.001 to 100 km2 (got " + *s + ")");
        o.minAreaM2 = r->first * 1e6;
        o.maxAreaM2 = r->second * 1e6;
    }
    if (auto s = args.value("shapes")) {
        o.families.clear();
        for (const auto& name : splitList(*s)) {
            bool found = false;
            for (plan::AreaFamily f : plan::allAreaFamilies())
                if (name == plan::areaFamilyName(f)) {
                    o.families.push_back(f);
                    found = true;
                }
            if (!found)
                return makeError(ErrorCode::InvalidInput,
                                 "--shapes: unknown shape '" + name + "' (use rectangle, rectilinear or polygonal)");
        }
        if (o.families.empty())
            return makeError(ErrorCode::InvalidInput, "--shapes: give at least one of rectangle, rectilinear, polygonal");
    }
    if (auto m = args.number("safety-margin"); m && *m && **m > 0)
        o.marginM = **m;
    return o;
}

// Written beside the target and renamed over it, so that an interrupted run never leaves half a file.
Status writeText(const std::filesystem::path& path, const std::string& text) {
    const std::filesystem::path tmp = path.string() + ".part";
    {
        std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
        f << text;
        f.close();
        if (!f)
            return makeError(ErrorCode::IoError, "cannot write " + path.string() + " (disk full or no permission?)");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec)
        return makeError(ErrorCode::IoError, "cannot write " + path.string() + ": " + ec.message());
    return {};
}

Status makeDir(const std::filesystem::path& dir) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec)
        return makeError(ErrorCode::IoError, "cannot create the directory " + dir.string() + ": " + ec.message());
    return {};
}

Status writeAreas(const std::vector<plan::GeneratedArea>& areas, const std::filesystem::path& dir) {
    if (auto st = makeDir(dir); !st)
        return st;
    for (const auto& a : areas)
        if (auto st = writeText(dir / plan::generatedAreaFileName(a), plan::generatedAreaGeoJson(a));
            !st)
            return st;
    return {};
}

std::string fixed(double v, int decimals) {
    char b[32];
    std::snprintf(b, sizeof b, "%.*f", decimals, v);
    return std::isfinite(v) ? b : "-";
}

} // namespace

int runEvalSurvey(const std::vector<std::string>& argv) {
    std::vector<OptionSpec> specs;
    for (const auto& s : missionOptionSpecs())
        if (s.name != "area" && s.name != "nofly" && s.name != "planner")
            specs.push_back(s);
    for (const char* name : {"generate", "seed", "zones", "size-km2", "shapes", "planners", "out"})
        specs.push_back({name});
    specs.push_back({"survey", false});
    auto args = Args::parse(argv, specs);
    if (!args)
        return reportError(args.error().message +
                           (args.error().message.find("--planner ") != std::string::npos ||
                                    args.error().message.find("--area") != std::string::npos
                                ? "; eval --survey takes the areas as arguments and the planners with --planners"
                                : ""));
    const bool survey = args->has("survey");
    const auto out = args->value("out");

    // The areas: files given, then generated ones.
    std::vector<plan::EvalArea> areas;
    std::vector<std::string> sources;
    for (const auto& path : args->positionals()) {
        auto a = plan::loadEvalArea(path);
        if (!a)
            return reportError(a.error());
        areas.push_back(std::move(a).value());
        sources.push_back(path);
    }
    if (!args->has("generate"))
        for (const char* flag : {"seed", "zones", "size-km2", "shapes"})
            if (args->has(flag))
                return reportError(std::string("--") + flag + ": goes with --generate N");
    if (args->has("generate")) {
        auto o = generatorOptions(*args);
        if (!o)
            return reportError(o.error());
        auto gen = plan::generateAreas(*o);
        if (!gen)
            return reportError(gen.error());
        int zones = 0;
        for (const auto& g : *gen) {
            areas.push_back(g.area);
            sources.push_back("generated");
            zones += static_cast<int>(g.area.noFly.size());
        }
        std::cerr << "generated " << gen->size() << " areas (seed " << o->seed << ", " << o->minZones << "-"
                  << o->maxZones << " no-fly zones, " << zones << " in all)\n";
        if (!survey) {
            if (!out)
                return reportError("eval --generate: give --out DIR for the area files (or --survey to compare the "
                                   "planners on them)");
            if (!args->positionals().empty())
                return reportError("eval --generate: area files are compared with --survey only");
            if (auto st = writeAreas(*gen, *out); !st)
                return reportError(st.error());
            for (const auto& g : *gen)
                std::cout << (std::filesystem::path(*out) / plan::generatedAreaFileName(g)).string() << "  "
                          << g.shape << ", " << fixed(g.areaM2 / 1e6, 3) << " km2, " << g.area.noFly.size()
                          << " no-fly zones\n";
            return kExitOk;
        }
        if (out)
            if (auto st = writeAreas(*gen, std::filesystem::path(*out) / "areas"); !st)
                return reportError(st.error());
    }
    if (!survey)
        return reportError("eval: --seed, --zones, --size-km2 and --shapes go with --generate, the mission options "
                           "and --planners with --survey (see photoflight-cli eval --help)");
    if (areas.empty())
        return reportError("eval --survey: no area given (area files, or --generate N)");

    std::vector<mission::PlannerKind> kinds;
    for (const auto& info : mission::plannerKinds())
        kinds.push_back(info.kind);
    if (auto list = args->value("planners")) {
        kinds.clear();
        for (const auto& name : splitList(*list)) {
            const auto k = mission::plannerKindFromId(name);
            if (!k)
                return reportError("--planners: unknown planner '" + name + "' (use " + mission::plannerKindIdList() +
                                   ")");
            kinds.push_back(*k);
        }
        if (kinds.empty())
            return reportError("--planners: give at least one planner");
    }
    if (out)
        if (auto st = makeDir(*out); !st)
            return reportError(st.error());

    std::vector<mission::SurveyComparison> results;
    for (std::size_t i = 0; i < areas.size(); ++i) {
        const auto& area = areas[i];
        auto m = mission::surveyMission(area, mission::surveyAircraft(), mission::PlannerOptions{});
        if (!m)
            return reportError(makeError(m.error().code, sources[i] + ": " + m.error().message));
        MissionInput in;
        in.mission = std::move(m).value();
        in.source = sources[i];
        in.fromMissionFile = true;
        if (auto st = applyMissionFlags(*args, in); !st)
            return reportError(st.error());
        if (i == 0)
            for (const auto& note : in.notes)
                std::cerr << "note: " << note << '\n';
        if (in.mission.aircraft.size() != 1)
            return reportError("eval --survey compares the planners for one aircraft: give at most one --aircraft");
        const auto report = mission::validateMission(in.mission);
        if (report.hasErrors())
            return reportError(makeError(ErrorCode::InvalidInput, sources[i] + " (" + area.name +
                                                                      "): " + report.errorSummary()));
        auto c = mission::compareOnMission(in.mission, area.name, kinds);
        if (!c)
            return reportError(c.error());
        std::cerr << "[" << i + 1 << "/" << areas.size() << "] " << area.name << ": lawnmower "
                  << fixed(c->lawnmower.timeS, 0) << " s";
        for (const auto& r : c->planners)
            std::cerr << ", " << mission::plannerKindInfo(r.kind).id << " "
                      << (r.m.ok ? fixed(mission::ratiosTo(r.m, *c).time, 2) + "x" : std::string("failed"));
        std::cerr << '\n';
        results.push_back(std::move(c).value());
    }
    std::cout << mission::surveyTable(results);

    if (out) {
        const std::filesystem::path dir(*out);
        if (auto st = writeText(dir / "survey.csv", mission::surveyCsv(results)); !st)
            return reportError(st.error());
        std::string chartError;
        const int charts = writeSurveyCharts(results, dir.string(), &chartError);
        if (charts < 0)
            return reportError(makeError(ErrorCode::IoError, chartError));
        std::cout << "\nWrote " << (dir / "survey.csv").string();
        if (charts > 0)
            std::cout << " and " << charts << " PNG picture(s) survey_<area>.png";
        if (args->has("generate"))
            std::cout << " and the generated areas in " << (dir / "areas").string();
        std::cout << '\n';
    }
    return kExitOk;
}

} // namespace pf::cli
