// libFuzzer harness: the camera and aircraft catalog reader (loadCatalog) on arbitrary files.
#include "tests/fuzz/fuzz_util.h"

#include "core/io/area_import.h"
#include "core/io/catalog.h"

#include <cstdint>
#include <cstdlib>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    pf::io::initGdal();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string path = pf::fuzz::writeScratch(data, size, ".json");
    auto cat = pf::io::loadCatalog(path);
    if (cat) {
        // The catalog file format is written by `photoflight-cli catalog --json`: it must read back.
        const std::string again = pf::io::catalogToJson(cat.value());
        const std::string back = pf::fuzz::writeScratch(
            reinterpret_cast<const uint8_t*>(again.data()), again.size(), ".json");
        if (!pf::io::loadCatalog(back)) std::abort();
    }
    return 0;
}
