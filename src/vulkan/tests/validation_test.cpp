// GPU category: --vulkan-validation hears the layer for the instance's whole life, from
// vkCreateInstance (a messenger chained into its create info) to teardown, and any message no
// render returned fails the test run.
#include <cloudscape/backend.h>

#include "vulkan/vulkan_context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

namespace {

// Every test of this binary: a validation message raised where no render result carries it
// (teardown) fails the run. ctest runs each test in its own process, so it is that test's.
class NoUnreportedValidationMessages : public ::testing::Environment {
public:
    void TearDown() override {
        const std::vector<std::string> late = cloudscape::takeVulkanValidationMessages();
        EXPECT_TRUE(late.empty()) << late.size()
                                  << " validation message(s) outside any render: " << late.front();
    }
};
[[maybe_unused]] ::testing::Environment* const kEnvironment =
    ::testing::AddGlobalTestEnvironment(new NoUnreportedValidationMessages);

// Sets an environment variable for one scope (the layer reads its settings at vkCreateInstance).
class ScopedEnvironment {
public:
    ScopedEnvironment(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name))
            old_ = old;
        ::setenv(name, value, 1);
    }
    ~ScopedEnvironment() {
        if (old_.empty())
            ::unsetenv(name_);
        else
            ::setenv(name_, old_.c_str(), 1);
    }

private:
    const char* name_;
    std::string old_;
};

bool anyContains(const std::vector<std::string>& messages, const std::string& text) {
    for (const std::string& m : messages)
        if (m.find(text) != std::string::npos)
            return true;
    return false;
}

} // namespace

// Best-practices checks (switched on through the layer's own environment setting) warn inside
// vkCreateInstance that VK_EXT_debug_utils is a debugging extension: only a messenger chained
// into the instance's create info can hear that.
TEST(VulkanValidation, AMessageRaisedWhileTheInstanceIsCreatedIsReported) {
    std::vector<std::string> messages;
    {
        const ScopedEnvironment bestPractices("VK_LAYER_ENABLES",
                                              "VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT");
        cloudscape::vulkan::Context context(-1, true);
        messages = context.takeValidationMessages();
    }
    cloudscape::takeVulkanValidationMessages(); // best practices may comment on teardown too
    ASSERT_FALSE(messages.empty());
    EXPECT_TRUE(anyContains(messages, "vkCreateInstance")) << messages.front();
}

// A buffer left alive when the device goes: the layer reports the leak inside vkDestroyDevice,
// after the last render, and the message reaches takeVulkanValidationMessages().
TEST(VulkanValidation, AMessageRaisedAtTeardownIsReported) {
    {
        cloudscape::vulkan::Context context(-1, true);
        // Deliberately leaked: the handle is dropped without vkDestroyBuffer.
        [[maybe_unused]] const vk::Buffer leaked = context.device.createBuffer(
            vk::BufferCreateInfo({}, 256, vk::BufferUsageFlagBits::eStorageBuffer));
        EXPECT_TRUE(context.takeValidationMessages().empty());
    }
    const std::vector<std::string> late = cloudscape::takeVulkanValidationMessages();
    ASSERT_FALSE(late.empty()) << "the leak went unreported";
    EXPECT_TRUE(anyContains(late, "VkBuffer")) << late.front();
}

TEST(VulkanValidation, AContextWithoutProblemsSaysNothing) {
    { cloudscape::vulkan::Context context(-1, true); }
    EXPECT_TRUE(cloudscape::takeVulkanValidationMessages().empty());
}
