// Every ranged scene key rejects values just outside its documented range and accepts its ends,
// for each kind of key: integers, numbers, and each component of the 3-vectors. The ranges are
// read from the generated reference (docs/SCENE.md's table, the same text users read), and the
// hand-written cases below pin a key of each kind to its range independently of that table.
#include <cloudscape/error.h>
#include <cloudscape/scene.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

using cloudscape::Scene;

namespace {

struct RangedKey {
    std::string key;
    std::string type; // "integer", "number" or "array of 3 numbers"
    std::string rangeText;
    double min = 0.0, max = 0.0;
};

std::vector<RangedKey> rangedKeys() {
    std::vector<RangedKey> keys;
    std::istringstream md(cloudscape::sceneDocumentationMarkdown());
    std::string line;
    while (std::getline(md, line)) {
        if (line.rfind("## Quality tiers", 0) == 0)
            break; // the key table ends; the tiers' table follows
        if (line.rfind("| `", 0) != 0)
            continue;
        // | `key` | type | unit | `default` | range | meaning |
        std::vector<std::string> cells;
        size_t start = 2;
        for (int i = 0; i < 5; ++i) {
            const size_t bar = line.find(" | ", start);
            cells.push_back(line.substr(start, bar - start));
            start = bar + 3;
        }
        const std::string range = cells[4];
        if (range == "-")
            continue;
        RangedKey k;
        k.key = cells[0].substr(1, cells[0].size() - 2); // strip the backquotes
        k.type = cells[1];
        k.rangeText = range;
        if (std::sscanf(range.c_str(), "[%lf, %lf]", &k.min, &k.max) != 2) {
            ADD_FAILURE() << "unreadable range " << range << " of " << k.key;
        }
        keys.push_back(k);
    }
    return keys;
}

std::string number(double v, bool integer) {
    char buf[64];
    if (integer)
        std::snprintf(buf, sizeof buf, "%.0f", v);
    else
        std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
}

// The error of applying key=value to a default scene ("" if it was accepted).
std::string errorOf(const std::string& key, const std::string& value) {
    Scene s;
    try {
        cloudscape::applyOverride(s, key + "=" + value);
    } catch (const cloudscape::Error& e) {
        return e.what();
    }
    return "";
}

std::string vector3(double a, double b, double c) {
    return std::string("[") + number(a, false) + "," + number(b, false) + "," + number(c, false) +
           "]";
}

} // namespace

TEST(SceneRanges, EveryRangedKeyRejectsValuesJustOutside) {
    const std::vector<RangedKey> keys = rangedKeys();
    int integers = 0, numbers = 0, vectors = 0;
    for (const RangedKey& k : keys) {
        const bool integer = k.type == "integer";
        // Just outside: one unit for integers, a thousandth of the bound (at least 1e-3) else.
        const double below = integer ? k.min - 1 : k.min - std::max(1e-3, std::abs(k.min) * 1e-3);
        const double above = integer ? k.max + 1 : k.max + std::max(1e-3, std::abs(k.max) * 1e-3);
        const double inside = integer ? std::floor(0.5 * (k.min + k.max)) : k.min;
        std::vector<std::pair<std::string, bool>> values; // value, expected to be accepted
        if (k.type == "array of 3 numbers") {
            ++vectors;
            values.push_back({vector3(k.min, k.min, k.min), true});
            values.push_back({vector3(k.max, k.max, k.max), true});
            // Each component alone out of range, the others valid.
            for (int c = 0; c < 3; ++c)
                for (double bad : {below, above}) {
                    double v[3] = {k.min, k.min, k.min};
                    v[c] = bad;
                    values.push_back({vector3(v[0], v[1], v[2]), false});
                }
        } else {
            (integer ? integers : numbers) += 1;
            values.push_back({number(inside, integer), true});
            // Both ends are inclusive (the seed's printed maximum is rounded, so not that one).
            if (k.max < 2e9)
                values.push_back({number(k.max, integer), true});
            values.push_back({number(below, integer), false});
            values.push_back({number(above, integer), false});
        }
        for (const auto& [value, accepted] : values) {
            const std::string e = errorOf(k.key, value);
            if (accepted) {
                EXPECT_EQ(e, "") << k.key << " = " << value;
                continue;
            }
            EXPECT_NE(e.find(k.key), std::string::npos) << k.key << " = " << value << ": " << e;
            EXPECT_NE(e.find(k.rangeText), std::string::npos)
                << k.key << " = " << value << ": " << e;
        }
    }
    EXPECT_GE(integers, 10);
    EXPECT_GE(numbers, 40);
    EXPECT_GE(vectors, 8);
}

TEST(SceneRanges, OneKeyOfEachKindByHand) {
    // An integer, a number, and a vector of each sign convention, with ranges written here.
    EXPECT_EQ(errorOf("render.width", "16"), "");
    EXPECT_NE(errorOf("render.width", "15").find("[16, 16384]"), std::string::npos);
    EXPECT_NE(errorOf("render.width", "16385").find("[16, 16384]"), std::string::npos);
    EXPECT_EQ(errorOf("weather.coverage", "1"), "");
    EXPECT_NE(errorOf("weather.coverage", "1.0001").find("[0, 1]"), std::string::npos);
    EXPECT_NE(errorOf("weather.coverage", "-0.0001").find("[0, 1]"), std::string::npos);
    EXPECT_EQ(errorOf("lighting.octave_factors", "[1,0,1]"), "");
    EXPECT_NE(errorOf("lighting.octave_factors", "[0.5,0.5,1.01]").find("lighting.octave_factors"),
              std::string::npos);
    EXPECT_NE(errorOf("lighting.octave_factors", "[-0.01,0.5,0.5]").find("[0, 1]"),
              std::string::npos);
    EXPECT_NE(errorOf("sun.irradiance", "[1,-1,1]").find("sun.irradiance"), std::string::npos);
    EXPECT_NE(errorOf("camera.position", "[0,2,2e7]").find("[-1e+07, 1e+07]"), std::string::npos);
    // Not a number at all, in a vector and alone.
    EXPECT_NE(errorOf("sky.zenith", "[0.1,\"blue\",0.3]").find("array of 3"), std::string::npos);
    // A number too large for a double is a one-line error naming the file, like any bad JSON.
    try {
        cloudscape::parseScene(R"({"sun": {"irradiance": [1, 1e999, 1]}})", "big.json");
        ADD_FAILURE() << "1e999 accepted";
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find("big.json"), std::string::npos) << e.what();
    }
}

TEST(SceneRanges, CrossKeyRulesAtTheirBoundaries) {
    // The cloud layer must be at least 10 m deep; the camera above the ground.
    auto parse = [](const std::string& json) {
        try {
            cloudscape::parseScene(json, "rules.json");
        } catch (const cloudscape::Error& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(parse(R"({"clouds": {"bottom_m": 2000, "top_m": 2010}})").find("clouds.top_m"),
              std::string::npos);
    EXPECT_EQ(parse(R"({"clouds": {"bottom_m": 2000, "top_m": 2010.5}})"), "");
    EXPECT_NE(parse(R"({"camera": {"position": [0, 0, 0]}})").find("altitude"), std::string::npos);
    EXPECT_EQ(parse(R"({"camera": {"position": [0, 0.01, 0]}})"), "");
}
