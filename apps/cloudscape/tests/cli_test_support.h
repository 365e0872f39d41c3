#pragma once
// What the CLI content tests share: running the tool (with the backend given explicitly by each
// test), scratch directories removed afterwards, and the EXR layers of a render.
#include <cloudscape/image_io.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace cloudscape::clitest {

namespace fs = std::filesystem;

inline std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

struct RunResult {
    int status = -1;
    std::string out;
    std::string err;
};

// Runs `prefix CLOUDSCAPE_CLI args` through the shell (prefix: environment settings or a
// wrapper such as taskset); captures stdout and stderr.
inline RunResult run(const std::string& args, const std::string& prefix = "") {
    static int counter = 0;
    const fs::path base =
        fs::temp_directory_path() /
        ("cloudscape_run_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    const std::string cmd = prefix + " " + CLOUDSCAPE_CLI + " " + args + " >" + base.string() +
                            ".out 2>" + base.string() + ".err";
    const int raw = std::system(cmd.c_str());
    RunResult r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = readBytes(base.string() + ".out");
    r.err = readBytes(base.string() + ".err");
    fs::remove(base.string() + ".out");
    fs::remove(base.string() + ".err");
    return r;
}

class TempDir {
public:
    TempDir() {
        static int counter = 0;
        path_ = fs::temp_directory_path() / ("cloudscape_clitest_" + std::to_string(::getpid()) +
                                             "_" + std::to_string(counter++));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TempDir() { fs::remove_all(path_); }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    std::string path() const { return path_.string(); }

private:
    fs::path path_;
};

// The cloud layer of an EXR render (cloud.R/G/B/A/T/Z) and its composite R, G, B, A.
struct Layers {
    int width = 0, height = 0;
    std::vector<float> r, g, b, a, cr, cg, cb, ca, ct, cz;
    size_t size() const { return r.size(); }
};

inline Layers readLayers(const std::string& path) {
    const ExrImage img = readExr(path);
    Layers l;
    l.width = img.width;
    l.height = img.height;
    l.r = img.channel("R");
    l.g = img.channel("G");
    l.b = img.channel("B");
    l.a = img.channel("A");
    l.cr = img.channel("cloud.R");
    l.cg = img.channel("cloud.G");
    l.cb = img.channel("cloud.B");
    l.ca = img.channel("cloud.A");
    l.ct = img.channel("cloud.T");
    l.cz = img.channel("cloud.Z");
    return l;
}

// The layers' own rules: cloud.A = 1 - cloud.T; radiance is finite and non-negative; the
// composite is opaque and holds at least the cloud's radiance (the background adds T * sky).
// For a still, also: a pixel with cloud (A > 0) has a finite, positive cloud distance and one
// without has +inf. Sequence frames do not keep that rule (see docs/TESTING.md): a pixel blended
// from its neighbours' marches or history keeps its own block's or nearest pixel's distance.
inline void expectConsistentLayers(const Layers& l, const std::string& what, bool still = true) {
    ASSERT_GT(l.size(), 0u) << what;
    size_t cloudy = 0, bad = 0;
    for (size_t i = 0; i < l.size() && bad < 5; ++i) {
        const bool depthOk = !still || (l.ca[i] > 0.0f ? std::isfinite(l.cz[i]) && l.cz[i] > 0.0f
                                                       : std::isinf(l.cz[i]) && l.cz[i] > 0.0f);
        const bool ok = std::abs(l.ca[i] - (1.0f - l.ct[i])) <= 1e-6f && l.ct[i] >= 0.0f &&
                        l.ct[i] <= 1.0f && depthOk && l.cz[i] > 0.0f && std::isfinite(l.cr[i]) &&
                        std::isfinite(l.cg[i]) && std::isfinite(l.cb[i]) && l.cr[i] >= 0.0f &&
                        l.cg[i] >= 0.0f && l.cb[i] >= 0.0f && l.a[i] == 1.0f &&
                        l.r[i] >= l.cr[i] - 1e-6f && l.g[i] >= l.cg[i] - 1e-6f &&
                        l.b[i] >= l.cb[i] - 1e-6f;
        if (!ok) {
            ++bad;
            ADD_FAILURE() << what << " pixel " << i << ": A " << l.ca[i] << " T " << l.ct[i]
                          << " Z " << l.cz[i] << " cloud " << l.cr[i] << " composite " << l.r[i];
        }
        cloudy += l.ca[i] > 0.0f;
    }
    if (still) {
        EXPECT_GT(cloudy, l.size() / 20) << what << ": the image must show cloud";
        EXPECT_LT(cloudy, l.size()) << what << ": and some sky";
    }
}

// Largest absolute difference over the cloud layer's radiance and transmittance.
inline double maxCloudDifference(const Layers& a, const Layers& b) {
    double m = 0.0;
    for (size_t i = 0; i < a.size(); ++i)
        for (auto ch : {&Layers::cr, &Layers::cg, &Layers::cb, &Layers::ct})
            m = std::max(m, static_cast<double>(std::abs((a.*ch)[i] - (b.*ch)[i])));
    return m;
}

} // namespace cloudscape::clitest
