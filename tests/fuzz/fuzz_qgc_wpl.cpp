// libFuzzer harness: the Mission Planner .waypoints waypoint reader (parseQgcWpl) on arbitrary text.
#include "core/io/area_import.h"
#include "core/io/qgc_wpl.h"

#include <cstdint>
#include <string>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    pf::io::initGdal();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto wp = pf::io::parseQgcWpl(text, "<fuzz>");
    (void)wp;
    return 0;
}
