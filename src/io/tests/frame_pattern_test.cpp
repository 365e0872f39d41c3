// Frame-name patterns: the frame number is inserted by hand, never by printf.
#include <cloudscape/error.h>
#include <cloudscape/frame_pattern.h>

#include <gtest/gtest.h>

using cloudscape::Error;
using cloudscape::FramePattern;

TEST(FramePattern, PadsToTheGivenWidthAndKeepsTheRestVerbatim) {
    EXPECT_EQ(FramePattern("out/f%04d.png").path(7), "out/f0007.png");
    EXPECT_EQ(FramePattern("out/f%04d.png").path(123456), "out/f123456.png");
    EXPECT_EQ(FramePattern("%d.exr").path(0), "0.exr");
    EXPECT_EQ(FramePattern("%d.exr").path(2147483647), "2147483647.exr");
    EXPECT_EQ(FramePattern("100%%-%03d.png").path(5), "100%-005.png");
    EXPECT_EQ(FramePattern("%09d").path(1), "000000001");
    EXPECT_EQ(FramePattern("a b'\"$(x)%d").path(3), "a b'\"$(x)3");
}

TEST(FramePattern, RefusesEverythingButOneFrameNumber) {
    for (const char* bad : {"%s.png", "%n", "%x%d", "%0999d", "%010d", "%0d", "%4d", "%d%d", "%",
                            "f%", "plain.png", "%%d", "%ld", "%-4d"})
        EXPECT_THROW(FramePattern{bad}, Error) << bad;
    EXPECT_THROW(FramePattern("%d").path(-1), Error);
}
