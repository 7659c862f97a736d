// libFuzzer harness: the area importer (importPolygons, OGR inside). The first byte picks the file
// extension, and with it the OGR driver, so one corpus reaches GeoJSON, KML and GML.
#include "tests/fuzz/fuzz_util.h"

#include "core/io/area_import.h"

#include <cstdint>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    pf::io::initGdal();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    static const char* const kExt[] = {".geojson", ".kml", ".gml", ".json"};
    const std::string ext = kExt[data[0] % 4];
    const std::string path = pf::fuzz::writeScratch(data + 1, size - 1, ext);
    auto polys = pf::io::importPolygons(path);
    (void)polys;
    return 0;
}
