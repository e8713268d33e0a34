// The report's HTML helpers that the viewer's difference mode and readout rely on.
#include <gtest/gtest.h>

#include <string>

#include "src/eval/report_html.hpp"

namespace ssfx::eval {
namespace {

TEST(ReportHtml, Base64MatchesTheRfc4648TestVectors) {
    // RFC 4648, section 10.
    EXPECT_EQ(html::base64(""), "");
    EXPECT_EQ(html::base64("f"), "Zg==");
    EXPECT_EQ(html::base64("fo"), "Zm8=");
    EXPECT_EQ(html::base64("foo"), "Zm9v");
    EXPECT_EQ(html::base64("foob"), "Zm9vYg==");
    EXPECT_EQ(html::base64("fooba"), "Zm9vYmE=");
    EXPECT_EQ(html::base64("foobar"), "Zm9vYmFy");
    // Bytes above 127 (a PNG's are) and the last two digits of the alphabet.
    EXPECT_EQ(html::base64(std::string("\xff\xfe\xfb\xef", 4)), "//777w==");
    EXPECT_EQ(html::base64(std::string("\0\0\0", 3)), "AAAA");
}

TEST(ReportHtml, PixelScriptDefinesOneDataUrlPerLabel) {
    const std::string s = html::pixelScript("lines", {{"truth", "foo"}, {"noaa", "fo"}});
    EXPECT_EQ(s,
              "window.ssfxPixels = window.ssfxPixels || {};\n"
              "window.ssfxPixels[\"lines\"] = {\"truth\":\"data:image/png;base64,Zm9v\","
              "\"noaa\":\"data:image/png;base64,Zm8=\"};\n");
}

}  // namespace
}  // namespace ssfx::eval
