// libFuzzer harness: the GPX waypoint reader (readGpx, OGR inside) on arbitrary files.
#include "tests/fuzz/fuzz_util.h"

#include "core/io/area_import.h"
#include "core/io/gpx.h"

#include <cstdint>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    pf::io::initGdal();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string path = pf::fuzz::writeScratch(data, size, ".gpx");
    auto wp = pf::io::readGpx(path);
    (void)wp;
    return 0;
}
