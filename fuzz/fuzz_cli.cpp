// Harness: the whole command line. The input is the argument list, one argument per line; it
// runs through the tool's own main (apps/cloudscape/main.cpp, compiled here with main renamed)
// in validate-only mode, so CLI11's parser, every subcommand's option checks, the scene loading
// with --tier/--set/--seed/--width, the frame-range, path and output checks all run, and each
// command stops before rendering or writing (apps/cloudscape/validate_only.h).
//
// The arguments name files, so the harness runs in a scratch directory holding a scene, a weather
// map, EXRs and an existing frame, and skips arguments that could reach outside it (absolute
// paths, "..", devices): a fuzzer must not read /dev/zero or probe the machine.
#include "fuzz_support.h"
#include "validate_only.h"

#include <cloudscape/image_io.h>
#include <cloudscape/scene.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

int cloudscape_cli_main(int argc, char** argv);

namespace {
namespace fs = std::filesystem;

void writeFixtures() {
    fs::copy_file(cloudscape::resolveScenePath("sunset"), "scene.json");
    std::ofstream("bad.json") << "{\"weather\": {\"coverage\": 2}}";
    std::vector<uint8_t> rgb(16 * 16 * 3);
    for (size_t i = 0; i < rgb.size(); ++i)
        rgb[i] = static_cast<uint8_t>(i * 7);
    cloudscape::writePngChannels("weather.png", 16, 16, 3, rgb);
    std::vector<float> ramp(16 * 16), half(8 * 8, 0.5f);
    for (size_t i = 0; i < ramp.size(); ++i)
        ramp[i] = 100.0f * static_cast<float>(i);
    cloudscape::writeExr("depth.exr", 16, 16, {{"R", ramp.data()}});
    cloudscape::writeExr("a.exr", 16, 16,
                         {{"R", ramp.data()}, {"G", ramp.data()}, {"B", ramp.data()}});
    cloudscape::writeExr("small.exr", 8, 8,
                         {{"R", half.data()}, {"G", half.data()}, {"B", half.data()}});
    fs::create_directories("out");
    fs::create_directories("frames");
    cloudscape::writePngChannels("frames/0000.png", 16, 16, 3, rgb);
}

bool mayEscapeTheSandbox(const std::string& arg) {
    if (!arg.empty() && (arg[0] == '/' || arg[0] == '~'))
        return true;
    for (const char* s : {"..", "=/", "/dev", "/proc", "/sys", "/run"})
        if (arg.find(s) != std::string::npos)
            return true;
    return false;
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    std::string dir = (fs::temp_directory_path() / "cloudscape-fuzz-cli-XXXXXX").string();
    if (!::mkdtemp(dir.data()) || ::chdir(dir.c_str()) != 0) {
        std::perror("fuzz_cli: scratch directory");
        std::abort();
    }
    writeFixtures();
    std::freopen("/dev/null", "w", stdout); // help texts and scene-doc
    cloudscape::cli::setValidateOnly(true);
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<std::string> args{"cloudscape"};
    std::string current;
    for (size_t i = 0; i < size; ++i) {
        if (data[i] != '\n') {
            current += static_cast<char>(data[i]);
            continue;
        }
        args.push_back(current);
        current.clear();
    }
    if (!current.empty())
        args.push_back(current);
    if (args.size() > 64)
        return -1;
    std::vector<char*> argv;
    for (std::string& a : args) {
        if (a.find('\0') != std::string::npos || mayEscapeTheSandbox(a))
            return -1;
        argv.push_back(a.data());
    }
    argv.push_back(nullptr);
    try {
        cloudscape_cli_main(static_cast<int>(args.size()), argv.data());
    } catch (const cloudscape::cli::ValidationComplete&) {
    }
    return 0;
}
