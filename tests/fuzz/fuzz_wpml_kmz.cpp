// libFuzzer harness: the DJI WPML .kmz reader (readWpmlKmz) on arbitrary bytes written as a .kmz
// file: the ZIP reading through /vsizip/, the XML parsing and the wayline reading.
#include "core/io/area_import.h"
#include "core/io/wpml_kmz.h"
#include "tests/fuzz/fuzz_util.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    pf::io::initGdal();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string path = pf::fuzz::writeScratch(data, size, ".kmz");
    auto wp = pf::io::readWpmlKmz(path);
    (void)wp;
    return 0;
}
