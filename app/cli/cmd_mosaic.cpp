// photoflight-cli mosaic: the photos of a flight to a georeferenced GeoTIFF mosaic, with
// footprints, seams and gaps as a GeoPackage, and a report of the photos that do not match the
// plan.
#include "app/cli/args.h"
#include "app/cli/commands.h"

#include "core/io/catalog.h"
#include "core/mosaic/mosaic_builder.h"
#include "core/mosaic/mosaic_report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace pf::cli {

const char* const kMosaicUsage =
    "Usage: photoflight-cli mosaic PHOTOS... --out MOSAIC.tif [options]\n"
    "\n"
    "Stitches the photos of a survey flight into one georeferenced image (direct georeferencing: "
    "no\n"
    "feature matching, minutes on a laptop). PHOTOS are JPEG files or directories of them (*.jpg,\n"
    "*.jpeg, not recursive).\n"
    "\n"
    "Each photo's pose comes from its EXIF/XMP: GPS position; altitude above take-off (DJI's XMP\n"
    "RelativeAltitude, else the GPS altitude minus the take-off altitude); gimbal yaw, pitch and "
    "roll\n"
    "(XMP), else the EXIF image direction, else the planned heading, else the flight track; "
    "looking\n"
    "straight down when no pitch is given. A photo without GPS takes the plan's photo points in\n"
    "capture order. The camera comes from the catalog by EXIF make/model (or --camera), else from "
    "the\n"
    "EXIF 35 mm focal length, else from the plan's footprint. Every ground pixel is taken from "
    "the\n"
    "photo that sees it most from above, over flat ground at the take-off height.\n"
    "\n"
    "Options:\n"
    "  --out FILE.tif          the mosaic: tiled GeoTIFF with overviews (cloud-optimised layout), "
    "in\n"
    "                          the site's UTM zone; JPEG-compressed with a transparency mask\n"
    "  --plan DIR|FILE         the plan (a directory written by photoflight-cli plan --out DIR, or "
    "its\n"
    "                          plan.geojson): photos are matched to its photo points (missing, "
    "extra and\n"
    "                          far-off photos are listed) and coverage is measured against its "
    "area\n"
    "  --aircraft NAME         match the photos to this aircraft's photo points only\n"
    "  --camera NAME           the catalog camera of every photo (photoflight-cli catalog lists "
    "them)\n"
    "  --catalog FILE          a catalog file instead of the bundled and user catalogs\n"
    "  --gsd CM                output resolution in cm per pixel (default: the photos' median)\n"
    "  --feather M             blend neighbouring photos across seams over M metres (default 0: "
    "sharp\n"
    "                          seams)\n"
    "  --takeoff-alt M         take-off altitude above sea level, for photos that give only a GPS\n"
    "                          altitude (with --plan it is estimated from the planned altitudes)\n"
    "  --match-tolerance M     a photo further than this from every planned point is reported\n"
    "                          (default: 40 % of the planned photo spacing, at least 3 m)\n"
    "  --max-view-angle DEG    ground seen further than this from the vertical is not used (60)\n"
    "  --dem FILE              refused: the mosaic projects the photos on flat ground at the take-off\n"
    "                          height (terrain models are used by plan and validate to follow the terrain)\n"
    "  --vectors FILE.gpkg     footprints, seams, gaps, camera positions and missing photos "
    "(default:\n"
    "                          beside the mosaic, MOSAIC.gpkg)\n"
    "  --lossless              DEFLATE compression with an alpha band instead of JPEG\n"
    "  --threads N             worker threads (default: all cores)\n"
    "  --quiet                 no progress on stderr\n"
    "\n"
    "Photos that cannot be used (unreadable or damaged, no position and no plan, another site) "
    "are\n"
    "named with the reason and left out; the rest is mosaicked.\n"
    "Exit codes: 0 mosaic written, 2 bad input (no photo usable, bad option), 1 internal error.\n";

namespace {

bool isPhotoFile(const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".jpg" || ext == ".jpeg";
}

// Progress on stderr: a line per stage, and every 10 % within it.
class ProgressPrinter {
public:
    explicit ProgressPrinter(bool quiet) : m_quiet(quiet) {}
    void operator()(double f, const std::string& stage) {
        if (m_quiet)
            return;
        const int tenth = static_cast<int>(f * 10.0);
        if (stage == m_stage && tenth == m_tenth)
            return;
        m_stage = stage;
        m_tenth = tenth;
        std::cerr << "mosaic: " << stage << ", " << static_cast<int>(std::lround(f * 100.0))
                  << " %\n";
    }

private:
    bool m_quiet;
    std::string m_stage;
    int m_tenth = -1;
};

} // namespace

int runMosaic(const std::vector<std::string>& argv) {
    auto args = Args::parse(argv, {{"out"},
                                   {"plan"},
                                   {"aircraft"},
                                   {"camera"},
                                   {"catalog"},
                                   {"gsd"},
                                   {"feather"},
                                   {"takeoff-alt"},
                                   {"match-tolerance"},
                                   {"max-view-angle"},
                                   {"dem"},
                                   {"vectors"},
                                   {"lossless", false},
                                   {"threads"},
                                   {"quiet", false}});
    if (!args)
        return reportError(args.error());
    if (args->has("dem"))
        return reportError(
            "--dem: the mosaic does not use terrain models: it projects the photos on flat ground at the "
            "take-off height (run without --dem; plan and validate take --dem to follow the terrain)");
    if (!args->value("out"))
        return reportError("mosaic needs --out FILE.tif (see photoflight-cli mosaic --help)");
    if (args->positionals().empty())
        return reportError(
            "mosaic needs photos: files or directories (see photoflight-cli mosaic --help)");

    mosaic::MosaicOptions opt;
    opt.outputPath = *args->value("out");
    for (const auto& p : args->positionals()) {
        std::error_code ec;
        if (std::filesystem::is_directory(p, ec)) {
            std::vector<std::string> inDir;
            for (const auto& e : std::filesystem::directory_iterator(p, ec))
                if (e.is_regular_file() && isPhotoFile(e.path()))
                    inDir.push_back(e.path().string());
            if (inDir.empty())
                return reportError(p + ": no .jpg or .jpeg photos in this directory");
            std::sort(inDir.begin(), inDir.end());
            opt.photos.insert(opt.photos.end(), inDir.begin(), inDir.end());
        } else {
            opt.photos.push_back(p);
        }
    }

    auto number = [&](const char* name, double* out, double scale, bool positive) -> bool {
        auto v = args->number(name);
        if (!v) {
            reportError(v.error());
            return false;
        }
        if (*v) {
            if (positive ? !(**v > 0) : !(**v >= 0)) {
                reportError(std::string("--") + name + ": expected a " +
                            (positive ? "positive" : "non-negative") + " number but got " +
                            *args->value(name));
                return false;
            }
            *out = **v * scale;
        }
        return true;
    };
    if (!number("gsd", &opt.gsdM, 0.01, true) || !number("feather", &opt.featherM, 1.0, false) ||
        !number("match-tolerance", &opt.matchToleranceM, 1.0, true) ||
        !number("max-view-angle", &opt.maxViewAngleDeg, 1.0, true))
        return kExitBadInput;
    if (opt.maxViewAngleDeg >= 85)
        return reportError("--max-view-angle: expected less than 85 degrees but got " +
                           *args->value("max-view-angle"));
    if (auto t = args->number("takeoff-alt"); !t) {
        return reportError(t.error());
    } else if (*t) {
        opt.takeoffAltitudeM = **t;
    }
    double threads = 0;
    if (!number("threads", &threads, 1.0, true))
        return kExitBadInput;
    opt.threads = static_cast<int>(threads);
    opt.jpegCompression = !args->has("lossless");
    if (auto v = args->value("vectors"))
        opt.vectorPath = *v;
    if (auto a = args->value("aircraft"))
        opt.planAircraft = *a;
    if (auto c = args->value("camera"))
        opt.cameraName = *c;

    auto catalog = args->value("catalog") ? io::loadCatalog(*args->value("catalog"))
                                          : io::loadDefaultCatalog();
    if (!catalog)
        return reportError(catalog.error());
    opt.catalog = catalog->cameras;
    if (auto p = args->value("plan")) {
        auto plan = mosaic::readPlannedFlight(*p);
        if (!plan)
            return reportError(plan.error());
        opt.plan = std::move(plan).value();
    }

    ProgressPrinter printer(args->has("quiet"));
    Progress progress([&](double f, const std::string& stage) { printer(f, stage); });
    auto report = mosaic::buildMosaic(opt, progress);
    if (!report)
        return reportError(report.error());
    for (const auto& f : report->findings)
        if (f.excluded)
            std::cerr << "photoflight-cli: warning: " << f.file << ": " << f.message << '\n';
    std::cout << mosaic::formatReport(*report);
    return kExitOk;
}

} // namespace pf::cli
