// The demo mission with a 4-minute battery for its first aircraft (the Falcon 8): it needs two
// sorties, the Phantom 4 Pro one; planned in about a second. Shared by the tests of sorties in
// files, uploads and the desktop application.
#pragma once

#include "core/io/mission_file.h"
#include "core/mission/mission.h"

#include <gtest/gtest.h>

#include <string>

namespace pf::test {

inline mission::Mission shortBatteryDemo() {
    auto m = io::readMissionFile(std::string(PF_RESOURCES_DIR) + "/demo/demo_mission.json");
    EXPECT_TRUE(m.ok()) << m.error().message;
    if (!m)
        return {};
    m->aircraft.front().enduranceMin = 4.0;
    return *m;
}

} // namespace pf::test
