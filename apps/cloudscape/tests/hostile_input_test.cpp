// The catalogue of bad and extreme inputs (issue 9): every command, file type and key kind is
// given something wrong, and each must fail with exit status 1 or 2, one line on stderr that
// names the file, key or value and what was expected, and no file written or clobbered.
// Extremes that are valid must render without NaN or Inf.
#include "cli_exec.h"

#include <cloudscape/image_io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <vector>

using namespace cli_test;

namespace {

struct BadInput {
    const char* name;
    std::vector<std::string> args; // "{dir}" is replaced by the scratch directory
    const char* expected;          // a substring the one-line message must contain
};

std::string nested(const std::string& open, const std::string& inner, const std::string& close,
                   int depth) {
    std::string text;
    for (int i = 0; i < depth; ++i)
        text += open;
    text += inner;
    for (int i = 0; i < depth; ++i)
        text += close;
    return text;
}

// Files the bad inputs refer to, written into the scratch directory.
void writeInputs(const ScratchDir& dir) {
    writeTextFile(dir.file("deep-arrays.json"), nested("[", "1", "]", 40000));
    writeTextFile(dir.file("deep-objects.json"), nested("{\"a\":", "1", "}", 40000));
    writeTextFile(dir.file("duplicate-key.json"),
                  R"({"weather": {"coverage": 0.2, "coverage": 0.9}})");
    writeTextFile(dir.file("duplicate-section.json"),
                  R"({"weather": {"coverage": 0.2}, "sun": {}, "weather": {"type": 0.5}})");
    writeTextFile(dir.file("huge-number.json"), R"({"weather": {"coverage": 1e999}})");
    writeTextFile(dir.file("top-array.json"), "[1, 2, 3]");
    writeTextFile(dir.file("empty.json"), "");
    writeTextFile(dir.file("garbage.json"), std::string("\x89PNG\r\n\x1a\n\0\0\xff", 11));
    writeTextFile(dir.file("unknown-key.json"), R"({"weather": {"coverag": 0.3}})");
    writeTextFile(dir.file("too-large.json"), "{\"seed\": 1}");
    std::filesystem::resize_file(dir.file("too-large.json"), 17u << 20); // sparse: cheap to make
    std::filesystem::create_directory(dir.file("a-directory.json"));
    std::filesystem::create_directory(dir.file("a-directory.png"));
    writeTextFile(dir.file("not-a-png.png"), "this is text");
    cloudscape::writePngChannels(dir.file("grey.png"), 4, 4, 1, std::vector<uint8_t>(16, 100));
    // A PNG wider than any image Cloudscape reads.
    cloudscape::writePngChannels(dir.file("too-wide.png"), 20000, 1, 1,
                                 std::vector<uint8_t>(20000, 128));
    const std::vector<float> zeros(16 * 16, 0.0f), ones(16 * 16, 1.0f);
    std::vector<float> withNan = ones;
    withNan[37] = std::numeric_limits<float>::quiet_NaN();
    cloudscape::writeExr(dir.file("no-rgb.exr"), 16, 16, {{"Z", zeros.data()}});
    cloudscape::writeExr(dir.file("finite.exr"), 16, 16,
                         {{"R", ones.data()}, {"G", ones.data()}, {"B", ones.data()}});
    cloudscape::writeExr(dir.file("nan.exr"), 16, 16,
                         {{"R", ones.data()}, {"G", withNan.data()}, {"B", ones.data()}});
    cloudscape::writeExr(dir.file("small.exr"), 8, 8,
                         {{"R", ones.data()}, {"G", ones.data()}, {"B", ones.data()}});
    writeTextFile(dir.file("keys-unknown.json"),
                  R"({"keyframes": [{"time_s": 0, "set": {"sun.local_solar_tme_h": 6}}]})");
    writeTextFile(dir.file("keys-backwards.json"),
                  R"({"keyframes": [{"time_s": 9, "set": {}}, {"time_s": 3, "set": {}}]})");
    writeTextFile(dir.file("keys-range.json"),
                  R"({"keyframes": [{"time_s": 0, "set": {"sun.local_solar_time_h": 30}}]})");
    writeTextFile(dir.file("keep.png"), "an existing output that a failed run must not touch");
}

std::vector<BadInput> catalogue() {
    const std::vector<std::string> tiny = {"--width", "16", "--height", "16"};
    auto render = [&](std::vector<std::string> extra) {
        std::vector<std::string> a = {"render", "--backend", "cpu"};
        a.insert(a.end(), tiny.begin(), tiny.end());
        a.insert(a.end(), extra.begin(), extra.end());
        return a;
    };
    auto set = [&](const std::string& assignment) {
        return render({"--set", assignment, "-o", "{dir}/keep.png"});
    };
    auto frames = [&](const std::string& output) {
        return render({"--frames", "0:3", "-o", "{dir}/" + output});
    };
    return {
        // Frame-name patterns are a user's string, never a printf format.
        {"frames %s", frames("%s.png"), "'%s' is not a frame number"},
        {"frames %n", frames("%n.png"), "'%n' is not a frame number"},
        {"frames %x", frames("%x.png"), "'%x' is not a frame number"},
        {"frames %0999d", frames("%0999d.png"), "the width after %0 must be 1 to 9"},
        {"frames two numbers", frames("%d-%04d.png"), "more than one frame number"},
        {"frames no number", frames("frame.png"), "no frame number"},
        {"frames trailing %", frames("f%d%.png"), "'%.' is not a frame number"},
        {"frames reversed", render({"--frames", "5:2", "-o", "{dir}/%d.png"}), "--frames '5:2'"},
        {"frames not a range", render({"--frames", "abc", "-o", "{dir}/%d.png"}), "expected A:B"},
        {"fps zero", render({"--frames", "0:1", "--fps", "0", "-o", "{dir}/%d.png"}), "--fps"},
        // Keyframe files (the scene files' parser and key table; the file and keyframe named).
        {"keyframes unknown key",
         render(
             {"--frames", "0:1", "--keyframes", "{dir}/keys-unknown.json", "-o", "{dir}/%d.png"}),
         "keys-unknown.json: keyframes[0]: unknown key 'sun.local_solar_tme_h'"},
        {"keyframes backwards",
         render(
             {"--frames", "0:1", "--keyframes", "{dir}/keys-backwards.json", "-o", "{dir}/%d.png"}),
         "keys-backwards.json: keyframes[1]: time_s = 3 comes before keyframes[0]'s 9"},
        {"keyframes out of range",
         render({"--frames", "0:1", "--keyframes", "{dir}/keys-range.json", "-o", "{dir}/%d.png"}),
         "keyframes[0]: sun.local_solar_time_h = 30 is out of range [0, 24]"},
        {"keyframes a directory",
         render({"--frames", "0:1", "--keyframes", "{dir}/a-directory.json", "-o", "{dir}/%d.png"}),
         "a-directory.json: is a directory; expected a keyframe file"},
        {"keyframes without frames",
         render({"--keyframes", "{dir}/keys-range.json", "-o", "{dir}/x.png"}),
         "give --frames A:B too"},
        {"bench keyframes missing",
         {"bench", "--frames", "1", "--keyframes", "{dir}/nothere.json"},
         "nothere.json: cannot open keyframe file"},
        // Scene files.
        {"nested arrays", render({"{dir}/deep-arrays.json", "-o", "{dir}/x.png"}),
         "deep-arrays.json: nested deeper than 16 levels"},
        {"nested objects", render({"{dir}/deep-objects.json", "-o", "{dir}/x.png"}),
         "deep-objects.json: nested deeper than 16 levels under 'a.a.a"},
        {"duplicate key", render({"{dir}/duplicate-key.json", "-o", "{dir}/x.png"}),
         "duplicate key 'weather.coverage'"},
        {"duplicate section", render({"{dir}/duplicate-section.json", "-o", "{dir}/x.png"}),
         "duplicate key 'weather'"},
        {"1e999 in a file", render({"{dir}/huge-number.json", "-o", "{dir}/x.png"}),
         "huge-number.json: a number too large for a double at or after 'weather.coverage'"},
        {"top-level array", render({"{dir}/top-array.json", "-o", "{dir}/x.png"}),
         "expected a JSON object at the top level"},
        {"empty scene", render({"{dir}/empty.json", "-o", "{dir}/x.png"}), "malformed JSON"},
        {"binary scene", render({"{dir}/garbage.json", "-o", "{dir}/x.png"}), "malformed JSON"},
        {"unknown key in a file", render({"{dir}/unknown-key.json", "-o", "{dir}/x.png"}),
         "unknown key 'weather.coverag'"},
        {"scene too large", render({"{dir}/too-large.json", "-o", "{dir}/x.png"}),
         "is too large for a scene file"},
        {"scene is a directory", render({"{dir}/a-directory.json", "-o", "{dir}/x.png"}),
         "a-directory.json: is a directory"},
        {"no such scene", render({"no-such-preset", "-o", "{dir}/x.png"}),
         "no-such-preset: no such scene file or preset"},
        // --set, one of each key kind.
        {"1e999 in --set", set("weather.coverage=1e999"),
         "weather.coverage = 1e999 is too large for a double"},
        {"nested --set", set("sun.irradiance=" + nested("[", "1", "]", 40)),
         "sun.irradiance: nested deeper than 16 levels"},
        {"number gets a word", set("weather.coverage=abc"),
         "weather.coverage expects number, got a string"},
        {"number gets NaN", set("weather.coverage=NaN"), "weather.coverage expects number"},
        {"number out of range", set("weather.coverage=1.5"),
         "weather.coverage = 1.5 is out of range [0, 1]"},
        {"integer gets a fraction", set("render.samples_per_pixel=1.5"),
         "render.samples_per_pixel expects an integer, got 1.5"},
        {"integer out of range", set("seed=-1"), "seed = -1 is out of range [0, 2147483647]"},
        {"bool gets a number", set("render.temporal=1"), "render.temporal expects boolean"},
        {"string gets a number", set("lighting.phase=3"),
         "lighting.phase '3': expected \"two-lobe\" or \"hg-draine\""},
        {"string not an option", set("lighting.phase=mie"), "lighting.phase 'mie'"},
        {"vector of two", set("sun.irradiance=[1,2]"), "sun.irradiance expects array of 3"},
        {"vector with a word", set("sun.irradiance=[1,\"a\",2]"),
         "sun.irradiance expects array of 3"},
        {"vector component out of range", set("sun.irradiance=[1,-1,1]"),
         "sun.irradiance = -1 is out of range"},
        {"position out of range", set("camera.position=[0,1e8,0]"),
         "camera.position = 1e+08 is out of range"},
        {"missing weather image", set("weather.image={dir}/nothere.png"), "nothere.png"},
        {"weather image not a PNG", set("weather.image={dir}/not-a-png.png"), "not-a-png.png"},
        {"weather image too wide", set("weather.image={dir}/too-wide.png"),
         "too-wide.png: cannot read PNG: 20000x1 pixels, expected 1 to 16384 on a side"},
        {"missing data field image", set("weather.field_image={dir}/nothere.png"), "nothere.png"},
        {"data field image not a PNG", set("weather.field_image={dir}/not-a-png.png"),
         "not-a-png.png"},
        {"data field image grey", set("weather.field_image={dir}/grey.png"),
         "grey.png: data field image has 1 channels, expected 4"},
        {"data field variation out of range", set("weather.base_variation=0.8"),
         "weather.base_variation = 0.8 is out of range [0, 0.5]"},
        {"missing depth file", set("render.depth_file={dir}/nothere.exr"), "nothere.exr"},
        {"depth file of another size", set("render.depth_file={dir}/small.exr"), "small.exr"},
        {"cross-key rule", set("clouds.top_m=1000"), "clouds.top_m (1000) must be at least"},
        {"no equals sign", set("weather.coverage"), "expected key=value"},
        {"empty key", set("=3"), "expected key=value"},
        {"unknown --set key", set("weather.coverag=0.3"), "unknown key 'weather.coverag'"},
        // Options of every command.
        {"render negative seed", render({"--seed", "-1", "-o", "{dir}/x.png"}), "--seed"},
        {"noise negative seed", {"noise", "--seed", "-1", "-o", "{dir}"}, "--seed: Value -1"},
        {"weather negative seed", {"weather", "--seed", "-1", "-o", "{dir}/w.png"}, "seed = -1"},
        {"pathtrace negative seed",
         {"pathtrace", "--seed", "-1", "--width", "16", "--height", "16", "-o", "{dir}/p.exr"},
         "seed = -1"},
        {"bench negative seed", {"bench", "--seed", "-1"}, "seed = -1"},
        {"width zero", {"render", "--width", "0", "-o", "{dir}/x.png"}, "render.width = 0"},
        {"width huge", {"render", "--width", "99999", "-o", "{dir}/x.png"}, "render.width = 99999"},
        {"width a word", {"render", "--width", "abc", "-o", "{dir}/x.png"}, "--width"},
        {"device negative", render({"--device", "-1", "-o", "{dir}/x.png"}), "--device"},
        {"backend unknown", {"render", "--backend", "gpu", "-o", "{dir}/x.png"}, "--backend 'gpu'"},
        {"tier unknown", render({"--tier", "ultra", "-o", "{dir}/x.png"}), "--tier 'ultra'"},
        {"camera path unknown",
         render({"--frames", "0:1", "--camera-path", "loop", "-o", "{dir}/%d.png"}), "loop"},
        {"output extension", render({"-o", "{dir}/x.jpg"}), "unsupported output extension '.jpg'"},
        {"output directory missing", render({"-o", "{dir}/no/such/x.png"}), "does not exist"},
        {"output is a directory", render({"-o", "{dir}/a-directory.png"}), "it is a directory"},
        {"pathtrace png", {"pathtrace", "-o", "{dir}/p.png"}, "expected a .exr output"},
        {"pathtrace spp zero", {"pathtrace", "--spp", "0", "-o", "{dir}/p.exr"}, "--spp"},
        {"pathtrace spp negative", {"pathtrace", "--spp", "-3", "-o", "{dir}/p.exr"}, "--spp"},
        {"compare missing file", {"compare", "{dir}/none.exr", "{dir}/finite.exr"}, "none.exr"},
        {"compare without R",
         {"compare", "{dir}/no-rgb.exr", "{dir}/finite.exr"},
         "no-rgb.exr: has no channel 'R'"},
        {"compare NaN",
         {"compare", "{dir}/finite.exr", "{dir}/nan.exr"},
         "nan.exr: 1 R/G/B values are NaN or infinite (the first at pixel 5, 2)"},
        {"compare sizes", {"compare", "{dir}/finite.exr", "{dir}/small.exr"}, "small.exr: size"},
        {"compare a PNG", {"compare", "{dir}/keep.png", "{dir}/finite.exr"}, "keep.png"},
        {"noise missing directory", {"noise", "-o", "{dir}/nowhere"}, "nowhere"},
        {"weather exr", {"weather", "-o", "{dir}/w.exr"}, "expected .png"},
        {"scene-doc missing directory",
         {"scene-doc", "-o", "{dir}/no/such/doc.md"},
         "does not exist"},
        {"unknown command", {"frobnicate"}, "unknown command 'frobnicate'"},
        {"unknown option", render({"--frobnicate", "-o", "{dir}/x.png"}), "--frobnicate"},
        {"no command", {}, "subcommand is required"},
    };
}

std::vector<std::string> expand(const std::vector<std::string>& args, const std::string& dir) {
    std::vector<std::string> out;
    for (std::string a : args) {
        for (size_t p = a.find("{dir}"); p != std::string::npos; p = a.find("{dir}"))
            a.replace(p, 5, dir);
        out.push_back(a);
    }
    return out;
}

} // namespace

// One ctest entry per bad input, so they run in parallel and a failure names its case.
class BadInputs : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, FailWithOneLineNamingTheFaultAndWriteNothing) {
    const BadInput& c = GetParam();
    ScratchDir dir;
    writeInputs(dir);
    const std::string dirPath = dir.file("").substr(0, dir.file("").size() - 1);
    const std::vector<std::string> before = dir.entries();
    const std::string kept = readFileBytes(dir.file("keep.png"));
    const ToolRun r = runCli(expand(c.args, dirPath));
    EXPECT_EQ(r.signal, 0) << "killed by signal " << r.signal;
    EXPECT_TRUE(r.status == 1 || r.status == 2) << "status " << r.status;
    EXPECT_EQ(r.stderrText.rfind("cloudscape: error: ", 0), 0u) << r.stderrText;
    EXPECT_EQ(std::count(r.stderrText.begin(), r.stderrText.end(), '\n'), 1) << r.stderrText;
    EXPECT_LE(r.stderrText.size(), 400u) << r.stderrText;
    EXPECT_NE(r.stderrText.find(c.expected), std::string::npos)
        << "expected '" << c.expected << "' in: " << r.stderrText;
    EXPECT_EQ(dir.entries(), before) << "left a file behind";
    EXPECT_EQ(readFileBytes(dir.file("keep.png")), kept) << "clobbered an existing output";
}

std::string caseName(const ::testing::TestParamInfo<BadInput>& info) {
    std::string name;
    for (char ch : std::string(info.param.name))
        name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
    return name;
}

INSTANTIATE_TEST_SUITE_P(Catalogue, BadInputs, ::testing::ValuesIn(catalogue()), caseName);

TEST(HostileInput, TheCatalogueCoversEveryCommand) {
    std::set<std::string> commands;
    for (const BadInput& c : catalogue())
        if (!c.args.empty())
            commands.insert(c.args[0]);
    for (const char* command :
         {"render", "noise", "weather", "pathtrace", "compare", "bench", "scene-doc", "frobnicate"})
        EXPECT_EQ(commands.count(command), 1u) << command;
    EXPECT_GE(catalogue().size(), 70u);
}

TEST(HostileInput, PathTraceResumeRefusesACorruptSampleCount) {
    ScratchDir dir;
    const std::string out = dir.file("truth.exr");
    const std::vector<std::string> args = {"pathtrace", "--width", "16", "--height", "16",
                                           "--spp",     "1",       "-o", out};
    ASSERT_EQ(runCli(args).status, 0);
    const cloudscape::ExrImage good = cloudscape::readExr(out);
    for (const std::string corrupt : {"-5", "", "99999999999999999999x"}) {
        std::map<std::string, std::string> attributes = good.attributes;
        attributes["cloudscape.samples"] = corrupt;
        std::vector<cloudscape::ExrChannel> channels;
        for (size_t i = 0; i < good.names.size(); ++i)
            channels.push_back({good.names[i], good.channels[i].data()});
        cloudscape::writeExr(out, good.width, good.height, channels, attributes);
        const std::string bytes = readFileBytes(out);
        std::vector<std::string> resume = args;
        resume[6] = "2";
        resume.push_back("--resume");
        const ToolRun r = runCli(resume);
        EXPECT_EQ(r.status, 1) << "'" << corrupt << "'";
        EXPECT_NE(r.stderrText.find("truth.exr: attribute cloudscape.samples = '" +
                                    corrupt.substr(0, 40) + "' is not a sample count"),
                  std::string::npos)
            << r.stderrText;
        EXPECT_EQ(readFileBytes(out), bytes) << "'" << corrupt << "': the checkpoint changed";
    }
}

TEST(HostileInput, ARenderThatCannotFitInMemoryFailsUpFrontWithTheEstimate) {
    // Only there: everywhere else (the normal build, gcc or clang) the budget is honoured.
    if (kUnderAddressSanitizer)
        GTEST_SKIP() << "AddressSanitizer's shadow memory does not fit in an address-space limit";
    ScratchDir dir;
    // A 4 GiB address-space budget (`ulimit -v`): a 16384^2 EXR needs about 24 GiB.
    const ToolRun r = runCli({"render", "--backend", "cpu", "--width", "16384", "--height", "16384",
                              "-o", dir.file("huge.exr")},
                             {4ull << 30});
    EXPECT_EQ(r.status, 1) << r.stderrText;
    EXPECT_NE(r.stderrText.find("16384x16384 needs about 24.1 GiB of memory"), std::string::npos)
        << r.stderrText;
    EXPECT_NE(r.stderrText.find("but 4.0 GiB is available"), std::string::npos) << r.stderrText;
    const ToolRun sequence = runCli({"render", "--backend", "cpu", "--width", "8192", "--height",
                                     "8192", "--frames", "0:1", "-o", dir.file("%d.png")},
                                    {4ull << 30});
    EXPECT_EQ(sequence.status, 1) << sequence.stderrText;
    EXPECT_NE(sequence.stderrText.find("8192x8192 needs about 8.1 GiB"), std::string::npos)
        << sequence.stderrText;
    EXPECT_TRUE(dir.entries().empty());
}

TEST(HostileInput, AFailedRenameSaysWhyAndKeepsTheOldFile) {
    ScratchDir dir;
    const std::string out = dir.file("immutable.png");
    writeTextFile(out, "old");
    // An immutable file cannot be replaced even by root. Not every filesystem has the flag.
    if (std::system(("chattr +i " + out + " 2>/dev/null").c_str()) != 0)
        GTEST_SKIP() << "chattr +i is not supported here";
    const ToolRun r =
        runCli({"render", "--backend", "cpu", "--width", "16", "--height", "16", "-o", out});
    std::system(("chattr -i " + out).c_str());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.stderrText.find("cannot write " + out + ": Operation not permitted"),
              std::string::npos)
        << r.stderrText;
    EXPECT_EQ(readFileBytes(out), "old");
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"immutable.png"});
}

// Valid but extreme scenes: each renders and every layer is finite (cloud.Z may be +inf where
// there is no cloud, never NaN).
class ExtremeScenes : public ::testing::TestWithParam<std::vector<std::string>> {};

TEST_P(ExtremeScenes, RenderWithoutNanOrInf) {
    ScratchDir dir;
    std::vector<std::string> args = {"render",   "--backend", "cpu", "--width",        "16",
                                     "--height", "16",        "-o",  dir.file("x.exr")};
    args.insert(args.end(), GetParam().begin(), GetParam().end());
    const ToolRun r = runCli(args);
    ASSERT_EQ(r.status, 0) << r.stderrText;
    const cloudscape::ExrImage img = cloudscape::readExr(dir.file("x.exr"));
    for (size_t c = 0; c < img.names.size(); ++c)
        for (float v : img.channels[c]) {
            const bool ok =
                img.names[c] == "cloud.Z" ? !std::isnan(v) && v >= 0.0f : std::isfinite(v);
            ASSERT_TRUE(ok) << img.names[c] << " = " << v;
        }
}

INSTANTIATE_TEST_SUITE_P(
    Catalogue, ExtremeScenes,
    ::testing::Values(
        std::vector<std::string>{"--set", "sun.elevation_deg=-10"},
        std::vector<std::string>{"--set", "sun.elevation_deg=-90"},
        std::vector<std::string>{"--set", "sun.from_time=true", "--set", "sun.latitude_deg=90",
                                 "--set", "sun.day_of_year=1", "--set",
                                 "sun.local_solar_time_h=24"},
        std::vector<std::string>{"--set", "camera.position=[0,100000,0]", "--set",
                                 "camera.pitch_deg=-89.9"},
        std::vector<std::string>{"--set", "camera.fov_deg=1"},
        std::vector<std::string>{"--set", "camera.fov_deg=170"},
        std::vector<std::string>{"--set", "planet.radius_m=1000"},
        std::vector<std::string>{"--set", "clouds.extinction_per_m=10"},
        std::vector<std::string>{"--seed", "2147483647"},
        std::vector<std::string>{"--set", "sun.irradiance=[0,0,0]", "--set",
                                 "lighting.ambient_strength=0"},
        std::vector<std::string>{"--set", "clouds.bottom_m=0", "--set", "clouds.top_m=20"},
        std::vector<std::string>{"--set", "weather.coverage=1", "--set", "weather.type=1"},
        std::vector<std::string>{"--set", "lighting.phase=hg-draine", "--set",
                                 "lighting.droplet_diameter_um=50"},
        std::vector<std::string>{"--set", "wind.speed_mps=500", "--set", "time_s=100000000"}),
    [](const ::testing::TestParamInfo<std::vector<std::string>>& info) {
        std::string name;
        for (const std::string& arg : info.param)
            if (arg.rfind("--", 0) != 0)
                for (char ch : arg)
                    name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        return name;
    });
