// End-to-end tests of the cloudscape tool: presets render to plausible images, rendering is
// deterministic, and every kind of bad input fails with one line and leaves no file behind.
#include <cloudscape/image_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;

namespace {

std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct RunResult {
    int status = -1;
    std::string stderrText;
    std::string stdoutText;
};

// Runs the tool with arguments (already shell-quoted where needed); captures stderr and stdout.
// CPU-category tests render on the CPU backend explicitly; the GPU tests cover Vulkan.
RunResult runTool(std::string args) {
    if (args.rfind("render ", 0) == 0)
        args.insert(7, "--backend cpu ");
    const std::string stem =
        (fs::temp_directory_path() / ("cloudscape_run_" + std::to_string(::getpid()))).string();
    const std::string cmd =
        std::string(CLOUDSCAPE_CLI) + " " + args + " >" + stem + ".out 2>" + stem + ".err";
    const int raw = std::system(cmd.c_str());
    RunResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.stderrText = readBytes(stem + ".err");
    r.stdoutText = readBytes(stem + ".out");
    fs::remove(stem + ".err");
    fs::remove(stem + ".out");
    return r;
}

class TempDir {
public:
    TempDir() {
        path_ = fs::temp_directory_path() /
                ("cloudscape_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter_++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    size_t entries() const {
        return static_cast<size_t>(std::distance(fs::directory_iterator(path_), {}));
    }

private:
    fs::path path_;
    static inline int counter_ = 0;
};

void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path) << text;
}

struct ImageMeasures {
    double cloudFraction = 0.0;  // pixels whose transmittance is below 0.5
    double meanLuminance = 0.0;  // of the composite
    double cloudLuminance = 0.0; // mean luminance of the cloud radiance where cloud covers
    bool finite = true;
};

ImageMeasures measure(const std::string& exrPath) {
    const cloudscape::ExrImage img = cloudscape::readExr(exrPath);
    const auto& r = img.channel("R");
    const auto& g = img.channel("G");
    const auto& b = img.channel("B");
    const auto& cr = img.channel("cloud.R");
    const auto& cg = img.channel("cloud.G");
    const auto& cb = img.channel("cloud.B");
    const auto& t = img.channel("cloud.T");
    ImageMeasures m;
    size_t cloudy = 0;
    double cloudLum = 0.0;
    for (size_t i = 0; i < r.size(); ++i) {
        for (float v : {r[i], g[i], b[i], cr[i], cg[i], cb[i], t[i]})
            m.finite = m.finite && std::isfinite(v);
        m.meanLuminance += 0.2126 * r[i] + 0.7152 * g[i] + 0.0722 * b[i];
        if (t[i] < 0.5f) {
            ++cloudy;
            cloudLum += (0.2126 * cr[i] + 0.7152 * cg[i] + 0.0722 * cb[i]) / (1.0 - t[i]);
        }
    }
    m.meanLuminance /= static_cast<double>(r.size());
    m.cloudFraction = static_cast<double>(cloudy) / static_cast<double>(r.size());
    m.cloudLuminance = cloudy ? cloudLum / static_cast<double>(cloudy) : 0.0;
    return m;
}

struct PresetBand {
    const char* name;
    double minCloud, maxCloud; // cloud fraction of the image
    double minLum, maxLum;     // mean luminance of the composite (linear)
};

// What each preset produces on a 128x72 render (measured 2026-12-01 with the atmosphere, issue
// 11: the fractions of the whole image, ground included, and the composite's mean linear
// luminance, in the comments), with a margin of 0.05 in cloud fraction and 10 % in luminance. A
// change that moves a preset out of its band must say why and update the band. (The atmosphere
// moved them: the sun is reddened by the air, the ground is lit, distant clouds are hazed; the
// overcast stratus is a thin layer lit through from above, brighter than the placeholder's. On
// 2026-12-02 the high-altitude layer brightened the four presets that have one: fair weather
// 0.525 -> 0.539, sunset 0.224 -> 0.272, dawn 0.092 -> 0.113, golden hour 0.594 -> 0.638; the
// cloud fraction counts the volumetric layer only and did not move. Also on 2026-12-02 the
// mountains preset turned on the clouds' shadow map and light shafts: 0.180 -> 0.147, the map
// alone brightening it 7 % (its shadows are lighter than the two cheap, upper-bound samples'),
// the shafts darkening it 24 % (at a 9 degree sun most of the air under the layer is shaded).
// Also on 2026-12-02 stills went to 4 samples per pixel (issue 15): every preset stayed in its
// band but golden hour, 0.638 -> 0.894, whose low sun lies in the view: at 1 sample the ray
// through each pixel's centre missed the 0.53 deg disc, at 4 jittered samples one catches it
// through thin cloud, and a single sample of the disc's radiance moves the image mean by about 1.
// The new figure is the better estimate of the pixels' mean; against the figures recorded here
// the others moved by at most 0.006 in cloud fraction and 0.004 in luminance, except overcast
// stratus 1.201 -> 1.278, still inside its band (not traced to a cause in that session). Later
// on 2026-12-02 fair weather, the default scene, got its landscape (gentle hills with fields and
// the clouds' shadow map, the camera 380 m up): 0.262 -> 0.274 in cloud fraction (the camera 378 m
// higher; not traced further), 0.539 -> 0.481 in luminance (the lower third is grass and fields
// of albedo about 0.08, in sun and cloud shadow, instead of a grey 0.15 plane); rebanded about the
// new figures with the same margins. On 2026-12-03 the storm's emission got the octaves' light
// scattered out of the cloud (docs/QUALITY.md section 8; the path tracer's glow more than
// doubles under-the-storm's mean): under-the-storm 0.380 -> 0.455, superstorm 0.175 -> 0.185
// with its cirrus plume too, storm-cycle 0.189 -> 0.193; the first two rebanded about the new
// figures with the same margins. On 2026-12-04 the storm's lighting was measured against the
// path tracer (docs/QUALITY.md section 8): storm.ambient_scale's default went from 2 to 1, which
// the path tracer measures under the storm (the underside was 1.5x its light), so
// under-the-storm 0.455 -> 0.326; and the superstorm preset was reframed (40 km away, 40 degree
// lens, over terrain, clear air, the shadow map on the clouds): 0.211 -> 0.176 in cloud fraction,
// 0.185 -> 0.192; storm-cycle got the same world (0.181 -> 0.176, 0.189 -> 0.188, in its band).
// The first two rebanded about the new figures with the same margins.)
const std::array<PresetBand, 15> kPresets = {{
    {"fair-weather-cumulus", 0.224, 0.324, 0.433, 0.529}, // 0.274, 0.481 (landscape)
    {"broken-stratocumulus", 0.50, 0.60, 0.43, 0.53},     // 0.551, 0.482
    {"overcast-stratus", 0.77, 0.87, 1.08, 1.32},         // 0.823, 1.201
    {"rain-storm", 0.65, 0.75, 0.30, 0.37},               // 0.703, 0.334
    {"sunset", 0.12, 0.22, 0.245, 0.299},                 // 0.169, 0.272
    {"above-the-deck", 0.42, 0.52, 0.42, 0.51},           // 0.469, 0.464
    {"inside-cloud", 0.92, 1.0, 0.49, 0.60},              // 0.969, 0.549
    {"dawn", 0.05, 0.15, 0.102, 0.124},                   // 0.097, 0.113
    {"golden-hour", 0.34, 0.44, 0.805, 0.983},            // 0.386, 0.894 (4 spp, 2026-12-02)
    {"dusk", 0.21, 0.31, 0.009, 0.011},                   // 0.259, 0.010 (sun 2.5 deg down)
    {"mountains", 0.10, 0.20, 0.132, 0.162},              // 0.151, 0.147 (shadow map, shafts)
    {"superstorm", 0.126, 0.226, 0.173, 0.211},           // 0.176, 0.192 (reframed, 2026-12-04)
    {"under-the-storm", 0.805, 0.905, 0.293, 0.359},      // 0.853, 0.326 (ambient x1)
    {"night", 0.275, 0.375, 7.19e-7, 8.79e-7},            // 0.325, 7.99e-7 (moonlit, 2026-12-02)
    {"storm-cycle", 0.131, 0.231, 0.170, 0.208},          // 0.181, 0.189 (lightning, 2026-12-02)
}};

} // namespace

TEST(Cli, EveryPresetRendersPlausibly) {
    TempDir dir;
    for (const PresetBand& p : kPresets) {
        const std::string out = dir.file(std::string(p.name) + ".exr");
        const RunResult r =
            runTool("render " + std::string(p.name) + " --width 128 --height 72 -o " + out);
        ASSERT_EQ(r.status, 0) << p.name << ": " << r.stderrText;
        const ImageMeasures m = measure(out);
        EXPECT_TRUE(m.finite) << p.name;
        EXPECT_GE(m.cloudFraction, p.minCloud) << p.name;
        EXPECT_LE(m.cloudFraction, p.maxCloud) << p.name;
        EXPECT_GE(m.meanLuminance, p.minLum) << p.name;
        EXPECT_LE(m.meanLuminance, p.maxLum) << p.name;
        std::printf("%-22s cloud fraction %.3f  mean luminance %.4g  cloud luminance %.4g\n",
                    p.name, m.cloudFraction, m.meanLuminance, m.cloudLuminance);
    }
}

TEST(Cli, RainStormHasDarkerCloudsThanFairWeather) {
    TempDir dir;
    const std::string fair = dir.file("fair.exr");
    const std::string storm = dir.file("storm.exr");
    ASSERT_EQ(runTool("render fair-weather-cumulus --width 96 --height 54 -o " + fair).status, 0);
    ASSERT_EQ(runTool("render rain-storm --width 96 --height 54 -o " + storm).status, 0);
    EXPECT_LT(measure(storm).cloudLuminance, 0.8 * measure(fair).cloudLuminance);
}

TEST(Cli, SameSceneRendersToIdenticalBytes) {
    TempDir dir;
    const std::string a = dir.file("a.png");
    const std::string b = dir.file("b.png");
    ASSERT_EQ(runTool("render --width 80 --height 45 -o " + a).status, 0);
    ASSERT_EQ(runTool("render --width 80 --height 45 -o " + b).status, 0);
    EXPECT_EQ(readBytes(a), readBytes(b));
    const std::string c = dir.file("c.png");
    ASSERT_EQ(runTool("render --width 80 --height 45 --seed 9 -o " + c).status, 0);
    EXPECT_NE(readBytes(a), readBytes(c)) << "the seed must matter";
}

TEST(Cli, SetOverrideChangesTheImage) {
    TempDir dir;
    const std::string a = dir.file("a.exr");
    const std::string b = dir.file("b.exr");
    ASSERT_EQ(runTool("render --width 96 --height 54 -o " + a).status, 0);
    ASSERT_EQ(runTool("render --width 96 --height 54 --set weather.coverage=0.1 -o " + b).status,
              0);
    EXPECT_LT(measure(b).cloudFraction, measure(a).cloudFraction);
}

namespace {

// Each case: arguments (with OUT standing for the output path), and text the error must name.
struct BadInput {
    const char* what;
    std::string args;
    const char* mustMention;
};

} // namespace

TEST(Cli, BadInputFailsWithOneLineAndLeavesNoFile) {
    TempDir dir;
    writeText(dir.file("malformed.json"), "{\"seed\": ");
    writeText(dir.file("unknown.json"), "{\"camera\": {\"zoom\": 2}}");
    writeText(dir.file("wrongtype.json"), "{\"weather\": {\"coverage\": \"high\"}}");
    writeText(dir.file("range.json"), "{\"weather\": {\"coverage\": 3}}");
    writeText(dir.file("noimage.json"), "{\"weather\": {\"image\": \"missing.png\"}}");
    writeText(dir.file("notpng.png"), "this is not a png");
    writeText(dir.file("badimage.json"), "{\"weather\": {\"image\": \"notpng.png\"}}");
    cloudscape::writePngChannels(dir.file("gray.png"), 4, 4, 2, std::vector<uint8_t>(32, 100));
    writeText(dir.file("twochannel.json"), "{\"weather\": {\"image\": \"gray.png\"}}");
    const size_t inputs = dir.entries();

    const std::vector<BadInput> cases = {
        {"missing scene", dir.file("nope.json") + " -o OUT", "nope.json"},
        {"malformed scene", dir.file("malformed.json") + " -o OUT", "malformed"},
        {"unknown key", dir.file("unknown.json") + " -o OUT", "camera.zoom"},
        {"wrong type", dir.file("wrongtype.json") + " -o OUT", "weather.coverage"},
        {"out of range", dir.file("range.json") + " -o OUT", "[0, 1]"},
        {"bad --set", "--set weather.coverage=-1 -o OUT", "weather.coverage"},
        {"missing weather image", dir.file("noimage.json") + " -o OUT", "missing.png"},
        {"unreadable weather image", dir.file("badimage.json") + " -o OUT", "notpng.png"},
        {"two-channel weather image", dir.file("twochannel.json") + " -o OUT", "channels"},
        {"unwritable output", "-o " + dir.file("no/such/dir/x.png"), "no/such/dir"},
        {"zero width", "--width 0 --height 36 -o OUT", "render.width"},
        {"negative height", "--width 64 --height -4 -o OUT", "render.height"},
        {"huge size", "--width 100000 --height 36 -o OUT", "render.width"},
        {"unknown extension", "-o " + dir.file("x.jpg"), ".jpg"},
    };
    for (const BadInput& c : cases) {
        std::string args = c.args;
        const std::string out = dir.file("out.png");
        if (auto pos = args.find("OUT"); pos != std::string::npos)
            args.replace(pos, 3, out);
        const bool sized = args.find("--width") != std::string::npos;
        const RunResult r =
            runTool("render " + std::string(sized ? "" : "--width 64 --height 36 ") + args);
        EXPECT_NE(r.status, 0) << c.what;
        EXPECT_NE(r.stderrText.find(c.mustMention), std::string::npos)
            << c.what << ": " << r.stderrText;
        EXPECT_EQ(std::count(r.stderrText.begin(), r.stderrText.end(), '\n'), 1)
            << c.what << ": " << r.stderrText;
        EXPECT_EQ(dir.entries(), inputs) << c.what << " left a file behind";
    }
}

TEST(Cli, FailedRenderLeavesAnExistingOutputUntouched) {
    TempDir dir;
    const std::string out = dir.file("keep.png");
    writeText(out, "precious");
    const RunResult r = runTool("render --set weather.coverage=2 -o " + out);
    EXPECT_NE(r.status, 0);
    EXPECT_EQ(readBytes(out), "precious");
}

TEST(Cli, WeatherAndNoiseExports) {
    TempDir dir;
    const std::string weather = dir.file("weather.png");
    ASSERT_EQ(runTool("weather rain-storm -o " + weather).status, 0);
    int w = 0, h = 0, c = 0;
    const auto pixels = cloudscape::readPng(weather, w, h, c);
    EXPECT_EQ(w, 512);
    EXPECT_EQ(c, 3);
    bool anyRain = false;
    for (size_t i = 0; i < pixels.size(); i += 3)
        anyRain = anyRain || pixels[i + 1] > 200;
    EXPECT_TRUE(anyRain) << "rain cells should show in the green channel";

    const RunResult noise = runTool("noise -o " + dir.file(""));
    ASSERT_EQ(noise.status, 0) << noise.stderrText;
    for (const char* name : {"base_noise", "detail_noise", "curl_noise", "high_clouds"})
        for (const char* ext : {".png", ".raw", ".exr", ".json"})
            EXPECT_TRUE(fs::exists(dir.file(std::string(name) + ext))) << name << ext;
    EXPECT_EQ(fs::file_size(dir.file("base_noise.raw")), 128u * 128u * 128u * 4u);
    EXPECT_EQ(fs::file_size(dir.file("high_clouds.raw")), 512u * 512u * 3u);
}

TEST(Cli, AutoFallsBackToTheCpuWithANoticeWhenVulkanHasNoDevice) {
    TempDir dir;
    const std::string out = dir.file("x.png");
    // An ICD list naming no driver: the loader loads but finds no device.
    const std::string cmd =
        "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json " +
        std::string(CLOUDSCAPE_CLI) + " render --width 32 --height 18 -o " + out + " --stats 2>" +
        dir.file("err.txt") + " >" + dir.file("out.txt");
    ASSERT_EQ(std::system(cmd.c_str()), 0);
    const std::string err = readBytes(dir.file("err.txt"));
    EXPECT_NE(err.find("CPU backend"), std::string::npos) << err;
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(readBytes(dir.file("out.txt")).find("backend          cpu"), std::string::npos);
    EXPECT_TRUE(fs::exists(out));
    // Asking for Vulkan explicitly is an error that says what to install.
    const RunResult r =
        runTool("devices"); // sanity: the real devices list works without the override
    EXPECT_EQ(r.status, 0) << r.stderrText;
    const std::string explicitCmd =
        "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json " +
        std::string(CLOUDSCAPE_CLI) + " render --backend vulkan --width 32 --height 18 -o " +
        dir.file("y.png") + " 2>" + dir.file("err2.txt");
    EXPECT_NE(std::system(explicitCmd.c_str()), 0);
    const std::string err2 = readBytes(dir.file("err2.txt"));
    EXPECT_NE(err2.find("mesa-vulkan-drivers"), std::string::npos) << err2;
    EXPECT_FALSE(fs::exists(dir.file("y.png")));
}

TEST(Cli, CompareReportsMetricsAndWritesAHeatmap) {
    TempDir dir;
    const std::string a = dir.file("a.exr");
    const std::string b = dir.file("b.exr");
    ASSERT_EQ(runTool("render --width 64 --height 36 -o " + a).status, 0);
    ASSERT_EQ(runTool("render --width 64 --height 36 --set weather.coverage=0.6 -o " + b).status,
              0);
    const std::string out = dir.file("same.txt");
    ASSERT_EQ(
        std::system((std::string(CLOUDSCAPE_CLI) + " compare " + a + " " + a + " >" + out).c_str()),
        0);
    const std::string same = readBytes(out);
    EXPECT_NE(same.find("SSIM (display luminance)           1.0000"), std::string::npos) << same;
    EXPECT_NE(same.find("inf dB"), std::string::npos) << same;
    ASSERT_EQ(std::system((std::string(CLOUDSCAPE_CLI) + " compare " + a + " " + b + " --heatmap " +
                           dir.file("heat.png") + " >" + out)
                              .c_str()),
              0);
    EXPECT_EQ(readBytes(out).find("1.0000"), std::string::npos) << "different scenes differ";
    EXPECT_TRUE(fs::exists(dir.file("heat.png")));
    EXPECT_NE(runTool("compare " + a + " " + dir.file("missing.exr")).status, 0);
}

TEST(Cli, FrameSequencesResumeWithoutRedoingFinishedFrames) {
    TempDir dir;
    const std::string pattern = dir.file("f%04d.png");
    const std::string args = "render --frames 0:5 --fps 12 --width 48 --height 28 -o " + pattern;
    ASSERT_EQ(runTool(args).status, 0);
    for (int f = 0; f <= 5; ++f)
        ASSERT_TRUE(fs::exists(dir.file("f000" + std::to_string(f) + ".png"))) << f;
    // Mark a finished frame so we can tell whether it is rewritten, and remove another.
    writeText(dir.file("f0001.png"), "kept");
    fs::remove(dir.file("f0004.png"));
    ASSERT_EQ(runTool(args).status, 0);
    EXPECT_EQ(readBytes(dir.file("f0001.png")), "kept") << "finished frames are left alone";
    EXPECT_TRUE(fs::exists(dir.file("f0004.png")));
    // --force renders everything again.
    ASSERT_EQ(runTool(args + " --force").status, 0);
    EXPECT_NE(readBytes(dir.file("f0001.png")), "kept");
    // Bad sequences are one-line errors that write nothing.
    const size_t files = dir.entries();
    EXPECT_NE(runTool("render --frames 5:2 -o " + pattern).status, 0);
    EXPECT_NE(runTool("render --frames x -o " + pattern).status, 0);
    EXPECT_NE(runTool("render --frames 0:2 -o " + dir.file("nopattern.png")).status, 0);
    EXPECT_NE(runTool("render --frames 0:2 --fps 0 -o " + pattern).status, 0);
    EXPECT_EQ(dir.entries(), files);
}

// --keyframes: a keyed coverage reaches the frames of a temporal sequence, is part of the
// checkpoint's fingerprint, and a bad file fails with one line before anything is written.
// (Each run costs about 3 s of noise generation, so the cases share as few runs as they can.)
TEST(Cli, KeyframesAnimateTheCoverageOfASequence) {
    TempDir dir;
    const std::string keys = dir.file("keys.json");
    writeText(keys, R"({"keyframes": [{"time_s": 0, "set": {"weather.coverage": 0.1}},
                                      {"time_s": 3, "set": {"weather": {"coverage": 0.9}}}]})");
    const std::string sequence = "render --frames 0:3 --fps 1 --width 48 --height 28 ";
    const RunResult keyed =
        runTool(sequence + "--keyframes " + keys + " -o " + dir.file("t%d.exr"));
    ASSERT_EQ(keyed.status, 0) << keyed.stderrText;
    std::vector<double> fractions;
    for (int f = 0; f <= 3; ++f)
        fractions.push_back(
            measure(dir.file(std::string("t").append(std::to_string(f)).append(".exr")))
                .cloudFraction);
    for (int f = 1; f <= 3; ++f)
        EXPECT_GT(fractions[f], fractions[f - 1]) << "frame " << f;
    EXPECT_GT(fractions[3], fractions[0] + 0.3) << fractions[0] << " -> " << fractions[3];

    // A rerun with other keyframes refuses the checkpoint rather than mixing two sequences.
    const std::string other = dir.file("other.json");
    writeText(other, R"({"keyframes": [{"time_s": 0, "set": {"weather.coverage": 0.2}}]})");
    fs::remove(dir.file("t3.exr"));
    const RunResult refused =
        runTool(sequence + "--keyframes " + other + " -o " + dir.file("t%d.exr"));
    EXPECT_EQ(refused.status, 1);
    EXPECT_NE(refused.stderrText.find("checkpoint of a different scene, camera path, keyframes"),
              std::string::npos)
        << refused.stderrText;
    EXPECT_FALSE(fs::exists(dir.file("t3.exr")));

    // A bad file: one line naming it, the keyframe and the key; nothing written.
    const std::string bad = dir.file("bad.json");
    writeText(bad, R"({"keyframes": [{"time_s": 0, "set": {"weather.coverage": 0.1}},
                                     {"time_s": 5, "set": {"weather.coverage": 3}}]})");
    const size_t files = dir.entries();
    const RunResult r = runTool(sequence + "--keyframes " + bad + " -o " + dir.file("b%d.png"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.stderrText.find(bad + ": keyframes[1]: weather.coverage = 3 is out of range"),
              std::string::npos)
        << r.stderrText;
    EXPECT_EQ(std::count(r.stderrText.begin(), r.stderrText.end(), '\n'), 1) << r.stderrText;
    EXPECT_NE(runTool("render --keyframes " + keys + " -o " + dir.file("s.png")).status, 0)
        << "keyframes need a sequence";
    EXPECT_EQ(dir.entries(), files);
}

TEST(Cli, BenchRunsACameraPathAndWritesJson) {
    TempDir dir;
    const std::string json = dir.file("bench.json");
    const RunResult r = runTool("bench --width 48 --height 28 --frames 3 --camera-path fast-pan "
                                "--json " +
                                json);
    ASSERT_EQ(r.status, 0) << r.stderrText;
    const std::string text = readBytes(json);
    EXPECT_NE(text.find("\"per_frame\""), std::string::npos);
    EXPECT_NE(text.find("\"time_ratio\""), std::string::npos);
    EXPECT_NE(text.find("\"ssim\""), std::string::npos);
    EXPECT_NE(runTool("bench --camera-path sideways --frames 1").status, 0);
    // Keyframes drive the bench's frames too.
    writeText(dir.file("keys.json"),
              R"({"keyframes": [{"time_s": 0, "set": {"sun.local_solar_time_h": 9}}]})");
    EXPECT_EQ(runTool("bench --width 32 --height 18 --frames 1 --set sun.from_time=true "
                      "--keyframes " +
                      dir.file("keys.json"))
                  .status,
              0);
    EXPECT_NE(runTool("bench --frames 1 --keyframes " + dir.file("none.json")).status, 0);
}

TEST(Cli, BenchSavesEachFramesImagesIntoANewDirectoryOnly) {
    TempDir dir;
    const std::string frames = dir.file("frames");
    const std::string json = dir.file("bench.json");
    const RunResult r = runTool("bench --width 32 --height 16 --frames 2 --camera-path fly-through "
                                "--json " +
                                json + " --save-frames " + frames);
    ASSERT_EQ(r.status, 0) << r.stderrText;
    // The first frame has no history: every pixel but the marched sixteenth (32 of 512) is a
    // fallback.
    EXPECT_NE(readBytes(json).find("\"fallback_fraction\": 0.9375"), std::string::npos)
        << readBytes(json);
    for (const char* name : {"frame-0000-temporal.png", "frame-0000-reference.png",
                             "frame-0000-source.png", "frame-0001-source.png"})
        EXPECT_TRUE(fs::exists(frames + "/" + name)) << name;
    // A directory with files in it is refused before anything renders, and keeps its files.
    const RunResult again =
        runTool("bench --width 32 --height 18 --frames 1 --save-frames " + frames);
    EXPECT_EQ(again.status, 1);
    EXPECT_NE(again.stderrText.find("expected a new or empty directory"), std::string::npos)
        << again.stderrText;
    EXPECT_EQ(std::distance(fs::directory_iterator(frames), {}), 6);
}

TEST(Cli, ReferenceTierSequencesMarchEveryPixel) {
    TempDir dir;
    const RunResult r = runTool("render --tier reference --frames 0:1 --width 32 --height 18 "
                                "--stats -o " +
                                dir.file("r%02d.png"));
    ASSERT_EQ(r.status, 0) << r.stderrText;
    EXPECT_NE(r.stdoutText.find("every pixel every frame"), std::string::npos) << r.stdoutText;
    EXPECT_TRUE(fs::exists(dir.file("r00.png")));
    EXPECT_TRUE(fs::exists(dir.file("r01.png")));
    EXPECT_NE(runTool("render --tier ultra -o " + dir.file("x.png")).status, 0);
}

// A temporal sequence's --stats says how many output pixels shared a march: the high tier's pan
// marches one pixel of every 4x4 block in its first frame (8x5 blocks of a 32x18 image) and of
// every 2x2 once it moves (16x9), where the entering edge's column of 9 blocks marches its other
// three pixels too (sample_gather.glsl.h): 2 * 576 / (40 + 144 + 27) = 5.5.
TEST(Cli, TemporalSequencesSayHowManyPixelsShareARay) {
    TempDir dir;
    const RunResult r = runTool("render --tier high --camera-path fast-pan --frames 0:1 --width 32 "
                                "--height 18 --stats -o " +
                                dir.file("t%02d.png"));
    ASSERT_EQ(r.status, 0) << r.stderrText;
    EXPECT_NE(r.stdoutText.find("a ray per 5.5 output pixels a frame"), std::string::npos)
        << r.stdoutText;
}

// The path tracer's output is progressive: it records its sample count, refuses to clobber an
// existing file, and resuming adds samples that equal a render made in one go, bit for bit.
TEST(Cli, PathTraceResumesAndNeverClobbers) {
    TempDir dir;
    const std::string small = "pathtrace --width 24 --height 16 --set camera.pitch_deg=20 ";
    const std::string a = dir.file("a.exr");
    const std::string b = dir.file("b.exr");
    ASSERT_EQ(runTool(small + "--spp 1 -o " + a).status, 0);
    EXPECT_EQ(cloudscape::readExr(a).attributes.at("cloudscape.samples"), "1");
    const std::string before = readBytes(a);

    RunResult again = runTool(small + "--spp 2 -o " + a);
    EXPECT_NE(again.status, 0);
    EXPECT_NE(again.stderrText.find("--resume"), std::string::npos) << again.stderrText;
    EXPECT_EQ(std::count(again.stderrText.begin(), again.stderrText.end(), '\n'), 1);
    EXPECT_EQ(readBytes(a), before);

    RunResult otherScene = runTool(small + "--set weather.coverage=0.9 --spp 2 --resume -o " + a);
    EXPECT_NE(otherScene.status, 0);
    EXPECT_NE(otherScene.stderrText.find("different scene"), std::string::npos)
        << otherScene.stderrText;
    EXPECT_EQ(readBytes(a), before);

    ASSERT_EQ(runTool(small + "--spp 3 --resume -o " + a).status, 0);
    ASSERT_EQ(runTool(small + "--spp 3 -o " + b).status, 0);
    EXPECT_EQ(cloudscape::readExr(a).attributes.at("cloudscape.samples"), "3");
    EXPECT_TRUE(readBytes(a) == readBytes(b)) << "the resumed file differs from the one-go one";
    // An independent stream is a different estimate of the same image.
    ASSERT_EQ(runTool(small + "--spp 3 --stream 1 -o " + dir.file("c.exr")).status, 0);
    EXPECT_NE(readBytes(dir.file("c.exr")), readBytes(b));

    RunResult png = runTool(small + "--spp 1 -o " + dir.file("x.png"));
    EXPECT_NE(png.status, 0);
    EXPECT_NE(png.stderrText.find(".exr"), std::string::npos) << png.stderrText;
    EXPECT_FALSE(fs::exists(dir.file("x.png")));
}
