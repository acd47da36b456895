// Status, error and decision names, and the report's text and JSON forms.
#include <gtest/gtest.h>

#include <string>

#include "symcr/symcr.hpp"
#include "report_access.hpp"

namespace {

TEST(EngineStatus, FormatsAndTruncatesSafely) {
  symcr::Status ok;
  EXPECT_TRUE(ok.ok());
  EXPECT_STREQ(ok.message(), "");
  symcr::Status error(symcr::Error::Corrupt, "bad %s at %d", "field", 42);
  EXPECT_FALSE(error.ok());
  EXPECT_EQ(error.error(), symcr::Error::Corrupt);
  EXPECT_STREQ(error.message(), "bad field at 42");
  const std::string long_text(1000, 'x');
  symcr::Status truncated(symcr::Error::Io, "%s", long_text.c_str());
  // Cut at 239 characters, and says so.
  EXPECT_EQ(std::string(truncated.message()), long_text.substr(0, 236) + "...");
  // A message that just fits is not marked.
  const std::string fits(239, 'y');
  EXPECT_EQ(std::string(symcr::Status(symcr::Error::Io, "%s", fits.c_str()).message()), fits);
}

TEST(EngineStatus, NamesEveryErrorAndDecision) {
  EXPECT_STREQ(symcr::error_name(symcr::Error::None), "None");
  EXPECT_STREQ(symcr::error_name(symcr::Error::Strict), "Strict");
  EXPECT_STREQ(symcr::error_name(symcr::Error::TooLarge), "TooLarge");
  EXPECT_STREQ(symcr::decision_name(symcr::Decision::Restored), "restored");
  EXPECT_STREQ(symcr::decision_name(symcr::Decision::Kept), "kept");
  EXPECT_STREQ(symcr::decision_name(symcr::Decision::Dropped), "dropped");
  EXPECT_STREQ(symcr::decision_name(symcr::Decision::Converted), "converted");
  EXPECT_STREQ(symcr::decision_name(symcr::Decision::Rejected), "rejected");
}

TEST(EngineReport, CountsAndAlignsText) {
  symcr::Report report;
  symcr::detail::ReportAccess::add(report, "copter.yaw", symcr::Decision::Converted, "renamed from heading", false);
  symcr::detail::ReportAccess::add(report, "copter.mission.items[].lat", symcr::Decision::Restored, "", false);
  symcr::detail::ReportAccess::add(report, "copter.old", symcr::Decision::Dropped, "field removed in this build", true);
  symcr::detail::ReportAccess::set_sequence(report, 7);
  EXPECT_EQ(report.count(symcr::Decision::Converted), 1u);
  EXPECT_EQ(report.count(symcr::Decision::Kept), 0u);
  const std::string text = report.to_text();
  EXPECT_NE(text.find("copter.yaw                  converted   renamed from heading\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("copter.old                  dropped   * field removed in this build\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("sequence 7, status: ok\n"), std::string::npos) << text;
}

TEST(EngineReport, LossesListOnlyWhatWasLost) {
  symcr::Report report;
  EXPECT_TRUE(report.lossless());
  EXPECT_EQ(report.losses_to_text(), "");
  symcr::detail::ReportAccess::add(report, "v.yaw", symcr::Decision::Kept, "field added in this build", false);
  symcr::detail::ReportAccess::add(report, "v.speed", symcr::Decision::Converted, "float64 -> int32", false);
  EXPECT_TRUE(report.lossless());
  EXPECT_EQ(report.losses_to_text(), "");
  symcr::detail::ReportAccess::add(report, "v.speed", symcr::Decision::Rejected, "12.5 is not an integer for int32", true);
  symcr::detail::ReportAccess::add(report, "v.old", symcr::Decision::Dropped, "field removed in this build", true);
  EXPECT_TRUE(report.ok());
  EXPECT_FALSE(report.lossless());
  EXPECT_EQ(report.losses_to_text(),
            "v.speed  rejected: 12.5 is not an integer for int32\n"
            "v.old  dropped: field removed in this build\n"
            "2 lossy decisions: checkpointed data this build does not hold (rejected values keep "
            "this build's)\n");
  symcr::detail::ReportAccess::set_status(report, symcr::Status(symcr::Error::Strict, "refused"));
  EXPECT_EQ(report.losses_to_text().rfind("restore failed: Strict: refused\nv.speed  rejected", 0), 0u)
      << report.losses_to_text();
}

TEST(EngineReport, JsonEscapesEverything) {
  symcr::Report report;
  symcr::detail::ReportAccess::add(report, "a\"b\\c\n\x01", symcr::Decision::Rejected, "bad \xff byte, ok \xc3\xa9", true);
  symcr::detail::ReportAccess::set_status(report, symcr::Status(symcr::Error::Strict, "no \"way\""));
  EXPECT_EQ(report.to_json(),
            "{\"ok\":false,\"error\":\"Strict\",\"message\":\"no \\\"way\\\"\",\"sequence\":0,"
            "\"entries\":[{\"path\":\"a\\\"b\\\\c\\n\\u0001\",\"decision\":\"rejected\","
            "\"detail\":\"bad \\ufffd byte, ok \xc3\xa9\",\"lossy\":true}],\"skipped\":[],"
            "\"warnings\":[]}");
}

TEST(EngineReport, SkippedCheckpointsAreRenderedInTextAndJson) {
  symcr::Report report;
  symcr::detail::ReportAccess::skipped(report).push_back({3, 12, "torn \"x\""});
  symcr::detail::ReportAccess::skipped(report).push_back({0, 0, "corrupt"});
  symcr::detail::ReportAccess::set_sequence(report, 11);
  const std::string text = report.to_text();
  EXPECT_NE(text.find("skipped slot 3 (sequence 12): torn \"x\"\nskipped slot 0 (sequence 0): "
                      "corrupt\nsequence 11, status: ok\n"),
            std::string::npos)
      << text;
  EXPECT_NE(report.to_json().find("\"skipped\":[{\"slot\":3,\"sequence\":12,\"reason\":"
                                  "\"torn \\\"x\\\"\"},{\"slot\":0,\"sequence\":0,"
                                  "\"reason\":\"corrupt\"}],\"warnings\":[]}"),
            std::string::npos)
      << report.to_json();
}

TEST(EngineReport, WarningsAreRenderedInTextAndJson) {
  symcr::Report report;
  symcr::detail::ReportAccess::warn(report, "fallback \"off\"");
  EXPECT_NE(report.to_text().find("warning: fallback \"off\"\nsequence 0, status: ok\n"),
            std::string::npos)
      << report.to_text();
  EXPECT_NE(report.to_json().find("\"warnings\":[\"fallback \\\"off\\\"\"]}"), std::string::npos)
      << report.to_json();
  ASSERT_EQ(report.warnings().size(), 1u);
}

}  // namespace
