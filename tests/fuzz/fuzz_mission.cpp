// libFuzzer harness: the mission reader (parseMissionJson) on arbitrary text; a parsed mission must
// also serialise and read back, since the GUI and the CLI both write what they read.
#include "core/io/area_import.h"
#include "core/io/mission_file.h"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    pf::io::initGdal();
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto m = pf::io::parseMissionJson(text, "<fuzz>");
    if (m) {
        const std::string again = pf::io::missionToJson(m.value());
        auto back = pf::io::parseMissionJson(again, "<round trip>");
        if (!back) std::abort(); // a mission we accepted must read back
    }
    return 0;
}
