// The order in which a dispatch's rows of workgroups cover the image (interface.glsl.h's
// interleavedRow): every row exactly once, and every contiguous share of the order, which is what
// lavapipe hands one thread, spread over the whole height.
#include "model/interface.glsl.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace cm = cloudscape::model;

TEST(DispatchOrder, EveryRowIsVisitedExactlyOnce) {
    for (uint32_t n = 1; n <= 600; ++n) {
        std::vector<int> visits(n, 0);
        for (uint32_t r = 0; r < n; ++r) {
            const uint32_t row = cm::interleavedRow(r, n);
            ASSERT_LT(row, n) << "r " << r << " of " << n;
            ++visits[row];
        }
        EXPECT_TRUE(std::all_of(visits.begin(), visits.end(), [](int v) { return v == 1; }))
            << n << " rows";
    }
}

TEST(DispatchOrder, EachThreadsShareTakesRowsFromBothHalves) {
    // Two to eight threads, each taking one contiguous share of the order (of at least a stride
    // of rows): a quarter to three quarters of every share's rows lie in the dispatch's upper
    // half (in image order the first thread's would all lie there).
    for (uint32_t n = 16; n < 300; ++n) {
        for (uint32_t threads = 2; threads <= 8; threads *= 2) {
            const uint32_t share = n / threads;
            if (share < uint32_t(cm::DISPATCH_ROW_STRIDE))
                continue;
            for (uint32_t t = 0; t < threads; ++t) {
                int upper = 0;
                for (uint32_t r = t * share; r < (t + 1) * share; ++r)
                    upper += 2 * cm::interleavedRow(r, n) < n ? 1 : 0;
                const double fraction = double(upper) / share;
                EXPECT_GE(fraction, 0.25) << n << " rows, thread " << t << " of " << threads;
                EXPECT_LE(fraction, 0.75) << n << " rows, thread " << t << " of " << threads;
            }
        }
    }
}
