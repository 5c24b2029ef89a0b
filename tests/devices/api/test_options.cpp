// Options: typed reads of a plugin's key=value options, with one message naming every bad or
// unknown key.
#include <gtest/gtest.h>

#include "devices/api/Options.h"

using armtrack::StreamRole;
using armtrack::devices::Options;

TEST(Options, ParseSplitsPairsAndBareKeysAreOn) {
  const QVariantMap m = Options::parse(QStringLiteral("rate=1000, port=/dev/rfcomm0,truth,=x"));
  EXPECT_EQ(m.size(), 3);
  EXPECT_EQ(m.value(QStringLiteral("rate")).toString(), QStringLiteral("1000"));
  EXPECT_EQ(m.value(QStringLiteral("port")).toString(), QStringLiteral("/dev/rfcomm0"));
  EXPECT_EQ(m.value(QStringLiteral("truth")).toString(), QStringLiteral("1"));
}

TEST(Options, TypedReadsWithinRangeAndDefaults) {
  Options o(Options::parse(QStringLiteral("rate=250.5,n=7,on=yes,off=0,name=left")));
  EXPECT_DOUBLE_EQ(o.number(QStringLiteral("rate"), 100.0, 1.0, 1000.0), 250.5);
  EXPECT_EQ(o.integer(QStringLiteral("n"), 1, 0, 10), 7);
  EXPECT_TRUE(o.flag(QStringLiteral("on"), false));
  EXPECT_FALSE(o.flag(QStringLiteral("off"), true));
  EXPECT_EQ(o.text(QStringLiteral("name")), QStringLiteral("left"));
  EXPECT_DOUBLE_EQ(o.number(QStringLiteral("absent"), 3.5, 0.0, 10.0), 3.5);
  EXPECT_EQ(o.error(), QString());
}

TEST(Options, EveryBadOrUnknownKeyIsNamedAndDefaultsKept) {
  Options o(Options::parse(QStringLiteral("rate=fast,n=11,on=maybe,typo=1,x=nan")));
  EXPECT_DOUBLE_EQ(o.number(QStringLiteral("rate"), 100.0, 1.0, 1000.0), 100.0);
  EXPECT_EQ(o.integer(QStringLiteral("n"), 1, 0, 10), 1);
  EXPECT_TRUE(o.flag(QStringLiteral("on"), true));
  EXPECT_DOUBLE_EQ(o.number(QStringLiteral("x"), 2.0, -1e9, 1e9), 2.0);  // NaN is not a number here
  const QString e = o.error();
  for (const char* needle :
       {"option 'rate' must be a number from 1 to 1000, not 'fast'",
        "option 'n' must be a whole number from 0 to 10, not '11'",
        "option 'on' must be on or off, not 'maybe'", "option 'x' must be a number",
        "unknown option 'typo' (known: rate, n, on, x)"})
    EXPECT_TRUE(e.contains(QLatin1String(needle))) << needle << " not in: " << e.toStdString();
}

TEST(Options, ImuRoleIsRequiredAndOneOfThree) {
  {
    Options o(Options::parse(QStringLiteral("role= Forearm ")));
    EXPECT_EQ(o.imuRole(), StreamRole::ForearmImu);
    EXPECT_EQ(o.error(), QString());
  }
  {
    Options o(Options::parse(QStringLiteral("role=upper")));
    EXPECT_EQ(o.imuRole(), StreamRole::UpperArmImu);
    EXPECT_EQ(o.error(), QString());
  }
  {
    Options o(QVariantMap{});
    o.imuRole();
    EXPECT_TRUE(
        o.error().contains(QStringLiteral("option 'role' is required: role=upper, "
                                          "role=forearm or role=trunk")))
        << o.error().toStdString();
  }
  {
    Options o(Options::parse(QStringLiteral("side=wrist")));
    o.imuRole(QStringLiteral("side"));
    EXPECT_EQ(o.error(), QStringLiteral("option 'side' must be upper, forearm or trunk (the "
                                        "sternum sensor), not 'wrist'"));
  }
}

// The third sensor, on the sternum, is the trunk IMU: "trunk" or "sternum", any case.
TEST(Options, ImuRoleTrunkIsTheSternumSensor) {
  for (const char* text : {"role=trunk", "role= TRUNK ", "role=Sternum"}) {
    Options o(Options::parse(QString::fromLatin1(text)));
    EXPECT_EQ(o.imuRole(), StreamRole::TrunkImu) << text;
    EXPECT_EQ(o.error(), QString()) << text;
  }
  // Near misses are refused with the three choices named, not taken for an arm segment.
  for (const char* text : {"role=trunks", "role=chest", "role=trunk imu", "role=torso"}) {
    Options o(Options::parse(QString::fromLatin1(text)));
    EXPECT_EQ(o.imuRole(), StreamRole::UpperArmImu) << text;
    EXPECT_TRUE(o.error().contains(QStringLiteral("must be upper, forearm or trunk")))
        << text << ": " << o.error().toStdString();
  }
}
