// A test helper shared by the layers whose keys it checks: a `--set` assignment that must be
// refused with an error naming the key.
#ifndef CLOUDSCAPE_IO_TESTS_REFUSED_OVERRIDE_H
#define CLOUDSCAPE_IO_TESTS_REFUSED_OVERRIDE_H

#include <cloudscape/error.h>
#include <cloudscape/scene.h>

#include <gtest/gtest.h>

#include <string>

// Applies `assignment` to a default scene; fails the test unless it throws a cloudscape::Error
// whose message names `key`.
inline void expectOverrideRefusedNaming(const std::string& assignment, const std::string& key) {
    cloudscape::Scene s;
    try {
        cloudscape::applyOverride(s, assignment);
    } catch (const cloudscape::Error& e) {
        EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
        return;
    }
    ADD_FAILURE() << assignment << " was accepted";
}

#endif
