#include "core/io/waypoint_format_util.h"

#include <gtest/gtest.h>

#include <clocale>

using namespace pf::io::detail;

TEST(FormatUtil, NumbersAreWrittenWithAPointAndNoTrailingZeros) {
    EXPECT_EQ(formatNumber(49.0107410000, 9), "49.010741");
    EXPECT_EQ(formatNumber(-0.0000000001, 9), "0");
    EXPECT_EQ(formatNumber(40.0, 4), "40");
    EXPECT_EQ(formatNumber(359.99999, 3), "360");
    EXPECT_EQ(formatNumber(1e-9, 9), "0.000000001");
}

TEST(FormatUtil, NumbersIgnoreTheProcessLocale) {
    // A GUI may switch LC_NUMERIC to a locale with a decimal comma; files must not change.
    const char* old = std::setlocale(LC_NUMERIC, nullptr);
    const std::string saved = old ? old : "C";
    if (!std::setlocale(LC_NUMERIC, "de_DE.UTF-8"))
        GTEST_SKIP() << "no German locale installed";
    EXPECT_EQ(formatNumber(8.5, 3), "8.5");
    EXPECT_EQ(parseNumber("8.5").value_or(0), 8.5);
    std::setlocale(LC_NUMERIC, saved.c_str());
}

TEST(FormatUtil, ParsesWholeFieldsOnly) {
    EXPECT_EQ(parseNumber(" +12.5 ").value_or(0), 12.5);
    EXPECT_EQ(parseNumber("-3e2").value_or(0), -300.0);
    for (const char* bad : {"", " ", "12,5", "1e", "nan", "inf", "12m", "0x10", "--1"})
        EXPECT_FALSE(parseNumber(bad).has_value()) << bad;
}

TEST(FormatUtil, SplitsLinesOfEveryEnding) {
    const auto a = splitLines("\xEF\xBB\xBFone\r\ntwo\nthree");
    ASSERT_EQ(a.size(), 3u);
    EXPECT_EQ(a[0], "one");
    EXPECT_EQ(a[1], "two");
    EXPECT_EQ(a[2], "three");
    EXPECT_EQ(splitLines("one\r\n").size(), 1u);
    EXPECT_TRUE(splitLines("").empty());
    EXPECT_EQ(splitLines("a\n\nb").size(), 3u);
}

TEST(FormatUtil, SplitsFieldsByTabsOrSpaces) {
    EXPECT_EQ(splitFields("1\t0\t\t3").size(), 4u); // an empty field between two tabs counts
    EXPECT_EQ(splitFields("1  0 3").size(), 3u);    // runs of spaces are one separator
    EXPECT_EQ(splitChar("a,,b,", ',').size(), 4u);
}

TEST(FormatUtil, KindsAndExtensions) {
    EXPECT_EQ(kindFromName(" Photo "), pf::route::WaypointKind::Photo);
    EXPECT_EQ(kindFromName("TRANSIT"), pf::route::WaypointKind::Transit);
    EXPECT_FALSE(kindFromName("hover").has_value());
    EXPECT_EQ(extensionOf("/a.b/c.PLAN"), ".plan");
    EXPECT_EQ(extensionOf("/a.b/c"), "");
    EXPECT_DOUBLE_EQ(normaliseHeading(-90), 270.0);
    EXPECT_DOUBLE_EQ(normaliseHeading(720), 0.0);
    std::vector<pf::route::Waypoint> w(5);
    inferNonPhotoKinds(w, {false, true, false, true, false});
    EXPECT_EQ(w[0].kind, pf::route::WaypointKind::Transit);
    EXPECT_EQ(w[2].kind, pf::route::WaypointKind::Turn);
    EXPECT_EQ(w[4].kind, pf::route::WaypointKind::Transit);
}
