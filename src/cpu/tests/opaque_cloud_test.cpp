// An opaque cloud hides what is behind it. The march stops once the view ray's transmittance falls
// below march.min_transmittance (a cost cut: what lies behind such a point adds at most that
// fraction of light); what it must not do is keep that residue as the cloud's transmittance, or
// the sun's disc (some 10^4 times brighter than the sky around it) shines through an overcast deck
// as a bright spot, as it did in the overcast-stratus preset.
#include <cloudscape/renderer.h>
#include <cloudscape/scene.h>

#include <gtest/gtest.h>

#include <cmath>

using cloudscape::Scene;

namespace {

double luminanceAt(const cloudscape::RenderResult& r, int x, int y) {
    const float* c = &r.composite[4 * (size_t(y) * r.width + x)];
    return 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
}

// A thick stratus deck over the whole sky, the camera on the ground looking straight at the sun
// through it (33x33 pixels: the middle pixel's ray is the sun's direction).
Scene deckInFrontOfTheSun() {
    Scene s;
    s.width = 33;
    s.height = 33;
    s.samplesPerPixel = 1;
    s.coverage = 1.0f;
    s.cloudType = 0.12f;
    s.typeVariation = 0.0f;
    s.extinctionPerM = 0.15f;
    s.erosion = 0.12f; // the overcast-stratus preset's: no holes at coverage 1
    s.sunElevationDeg = 45.0f;
    s.sunHeadingDeg = 20.0f;
    s.cameraPosition = {0.0f, 2.0f, 0.0f};
    s.cameraHeadingDeg = s.sunHeadingDeg;
    s.cameraPitchDeg = s.sunElevationDeg;
    s.cameraFovDeg = 10.0f;
    return s;
}

} // namespace

TEST(OpaqueCloud, AStoppedMarchLetsNothingThrough) {
    const Scene scene = deckInFrontOfTheSun();
    const cloudscape::RenderResult r = renderCpu(scene, cloudscape::prepareResources(scene));
    const int mid = scene.width / 2;
    // Where the march stopped early the cloud is opaque: transmittance exactly 0.
    const float centreT = r.cloud[4 * (size_t(mid) * r.width + mid) + 3];
    EXPECT_EQ(centreT, 0.0f) << "the march stopped below min_transmittance kept its residue";
    // The sun's pixel is no brighter than the deck a few degrees beside it (a ring of pixels
    // 3 degrees away): the deck's own light peaks toward the sun, but by a factor near 1, not the
    // 100+ of a disc seen through 1 % transmittance.
    double ring = 0.0;
    int n = 0;
    for (int y = 0; y < r.height; ++y)
        for (int x = 0; x < r.width; ++x) {
            const double d = std::hypot(x - mid, y - mid);
            if (d > 9.0 && d < 11.0) {
                ring += luminanceAt(r, x, y);
                ++n;
            }
        }
    ASSERT_GT(n, 0);
    EXPECT_LT(luminanceAt(r, mid, mid), 1.5 * ring / n);
}
