#include "core/io/mission_limits.h"

namespace pf::io {

namespace {

// ArduPilot, AP_Mission: every command takes AP_MISSION_EEPROM_COMMAND_SIZE = 15 bytes of the
// board's mission storage, less 4 bytes of version (AP_Mission::num_commands_max()), and command 0
// is the home. The storage is the StorageMission areas of libraries/StorageManager: on boards with
// 16 KB of storage (STORAGE_NUM_AREAS >= 13, the common Pixhawk-class flight controllers) 2422 +
// 2132 + 5204 bytes for Copter, (9758 - 4) / 15 = 650 commands (655 for Plane and Rover); boards
// with 32 KB add 9842 bytes (1,306). More only with the mission on the SD card: BRD_SD_MISSION
// reserves up to 64 kB there, "each waypoint uses 15 bytes" (its parameter documentation), 4,369.
constexpr std::size_t kArduPilotItems = 650;
// PX4, dataman: mission items are stored in NUM_MISSION_ITEMS_SUPPORTED slots, "Maximum number of
// mission items", default 500 (src/modules/dataman/Kconfig); a board's build may set more. PX4
// lowered it from 2000 to 500 so that missions also fit the RAM backend (SYS_DM_BACKEND).
constexpr std::size_t kPx4Items = 500;
// The ground stations add no limit of their own (Mission Planner's is "open ended", its issue 1644;
// QGroundControl leaves it to the vehicle): the autopilot finds out on upload, ArduPilot answering a
// MISSION_COUNT over its storage with MAV_MISSION_NO_SPACE. Hence the warning before a file is flown.

std::string thousands(std::size_t n) {
    std::string s = std::to_string(n);
    for (int i = static_cast<int>(s.size()) - 3; i > 0; i -= 3)
        s.insert(static_cast<std::size_t>(i), ",");
    return s;
}

} // namespace

const MissionItemLimit& missionItemLimit(Autopilot autopilot) {
    static const MissionItemLimit ardupilot{
        kArduPilotItems,
        "ArduPilot " + thousands(kArduPilotItems) +
            ", its home included (16 KB of mission storage; 1,306 with 32 KB, up to 4,369 on "
            "the SD card with BRD_SD_MISSION)"};
    static const MissionItemLimit px4{
        kPx4Items, "PX4 " + thousands(kPx4Items) +
                       " (unless its build sets NUM_MISSION_ITEMS_SUPPORTED higher)"};
    return autopilot == Autopilot::PX4 ? px4 : ardupilot;
}

std::size_t storedItems(std::size_t missionItems, Autopilot autopilot) {
    return autopilot == Autopilot::ArduPilot ? missionItems + 1 : missionItems;
}

bool fitsAutopilot(std::size_t missionItems, std::optional<Autopilot> autopilot) {
    if (autopilot)
        return storedItems(missionItems, *autopilot) <= missionItemLimit(*autopilot).items;
    return fitsAutopilot(missionItems, Autopilot::ArduPilot) &&
           fitsAutopilot(missionItems, Autopilot::PX4);
}

std::string itemLimitWarning(const std::string& flight, std::size_t missionItems,
                             std::optional<Autopilot> autopilot,
                             std::optional<std::size_t> itemsByDistance) {
    if (fitsAutopilot(missionItems, autopilot))
        return {};
    return itemLimitWarning(flight, std::vector<std::size_t>{missionItems}, autopilot,
                            itemsByDistance ? std::vector<std::size_t>{*itemsByDistance}
                                            : std::vector<std::size_t>{});
}

std::string itemLimitWarning(const std::string& flights,
                             const std::vector<std::size_t>& missionItems,
                             std::optional<Autopilot> autopilot,
                             const std::vector<std::size_t>& itemsByDistance) {
    if (missionItems.empty())
        return {};
    auto counts = [](const std::vector<std::size_t>& n) {
        std::string out;
        for (std::size_t i = 0; i < n.size(); ++i)
            out += (i == 0 ? "" : i + 1 == n.size() ? " and " : ", ") + thousands(n[i]);
        return out;
    };
    const std::string limitText = autopilot ? missionItemLimit(*autopilot).where
                                            : missionItemLimit(Autopilot::PX4).where + ", " +
                                                  missionItemLimit(Autopilot::ArduPilot).where;
    const bool one = missionItems.size() == 1;
    std::string out = flights + ": " + counts(missionItems) +
                      " mission items, more than an autopilot holds: " + limitText +
                      ". The vehicle may refuse " + (one ? "the mission" : "such a mission") +
                      " or keep only part of it";
    bool fewer = itemsByDistance.size() == missionItems.size();
    bool allFit = fewer;
    for (std::size_t i = 0; fewer && i < missionItems.size(); ++i) {
        fewer = itemsByDistance[i] < missionItems[i];
        allFit = allFit && fitsAutopilot(itemsByDistance[i], autopilot);
    }
    if (fewer)
        out += std::string("; with photos by distance along lanes ") +
               (one ? "it takes " : "they take ") + counts(itemsByDistance) + " items" +
               (allFit ? "" : ", still too many: a higher altitude needs fewer photos");
    return out;
}

} // namespace pf::io
