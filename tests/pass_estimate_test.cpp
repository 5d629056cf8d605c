// The arithmetic of a pass's bound (demo/common/pass_estimate.h) against hand computations.
#include <gtest/gtest.h>

#include "common/pass_estimate.h"

using namespace fxport::demo;

// Two Vector4 targets of 160x100 (256 000 B each) and a D24S8 buffer (64 000 B) at 10 GB/s:
// written once 576 000 B / 10 GB/s = 0.0576 ms. 20 000 fragments x 32 B at 8 GB/s = 0.08 ms, the
// larger: fill 0.08 ms. Fetches: 16 000 fragments x 3 + 4 000 x 13 = 100 000 at 0.5 Gtexel/s = 0.2 ms.
// Bound: max(0.08, 0.2) = 0.2 ms.
TEST(PassEstimate, FillIsTheLargerOfWriteOnceAndFragmentsAndTheBoundTheLargerOfFillAndFetch) {
    PassWork work;
    work.targets = {{256000, 10}, {256000, 10}, {64000, 10}};
    work.fragments = 20000;
    work.bytesPerFragment = 32;
    work.fragmentRateGBps = 8;
    work.fetchRuns = {{16000, 3, 3, false}, {4000, 13, 13, false}};
    work.fetchRateGTexelsPerSecond = 0.5;
    const PassEstimate e = estimate(work);
    EXPECT_DOUBLE_EQ(e.bytes, 576000);
    EXPECT_NEAR(e.fillMs, 0.08, 1e-12);
    EXPECT_DOUBLE_EQ(e.fetches, 100000);
    EXPECT_NEAR(e.fetchMs, 0.2, 1e-12);
    EXPECT_NEAR(e.boundMs(), 0.2, 1e-12);
    EXPECT_EQ(fetchesPerFragmentText(e, 20000), "5");  // 100 000 / 20 000

    // Few fragments: writing each target once is the larger fill term; fetches below it.
    work.fragments = 1000;
    work.fetchRuns = {{1000, 2, 2, false}};
    const PassEstimate f = estimate(work);
    EXPECT_NEAR(f.fillMs, 0.0576, 1e-12);
    EXPECT_NEAR(f.fetchMs, 2000 / 0.5e9 * 1e3, 1e-15);
    EXPECT_NEAR(f.boundMs(), 0.0576, 1e-12);
}

// The clears a pass executed add to its fragments' time (they write the same memory first):
// 8 MB of fragments at 64 GB/s and an 8 MB clear at 50 GB/s are 0.125 + 0.16 ms; alone, the
// fragments' term would have been below writing the target once (8 MB at 40 GB/s, 0.2 ms).
TEST(PassEstimate, ExecutedClearsAddToTheFragmentsTime) {
    PassWork work;
    work.targets = {{8e6, 40}};
    work.fragments = 2e6;
    work.bytesPerFragment = 4;
    work.fragmentRateGBps = 64;
    EXPECT_NEAR(estimate(work).fillMs, 0.2, 1e-12);
    work.clearedBytes = 8e6;
    work.clearRateGBps = 50;
    EXPECT_NEAR(estimate(work).fillMs, 0.125 + 0.16, 1e-12);
    work.clearRateGBps = 0;  // rate unknown: no clear term
    EXPECT_NEAR(estimate(work).fillMs, 0.2, 1e-12);
    // A compute pass (no fragments) after a clear: its writes once at its rate, then the clear.
    work.fragments = 0;
    work.targets = {{8e6, 400, 8e6}};
    work.clearRateGBps = 50;
    EXPECT_NEAR(estimate(work).fillMs, 0.02 + 0.16, 1e-12);
}

// Per-format rates add up target by target: 1 MB at 1 GB/s + 4 MB at 4 GB/s = 1 ms + 1 ms.
TEST(PassEstimate, EachTargetAtItsOwnRate) {
    PassWork work;
    work.targets = {{1e6, 1}, {4e6, 4}};
    EXPECT_NEAR(estimate(work).fillMs, 2.0, 1e-12);
    EXPECT_EQ(estimate(work).fetchMs, 0);  // no fetch rate: no fetch term
}

// A count the shader text cannot settle enters the bound with its least; the text says so.
TEST(PassEstimate, UncertainFetchCountsUseTheLeastAndSaySo) {
    PassWork work;
    work.fragments = 1000;
    work.fetchRuns = {{1000, 1, 4, false}};
    work.fetchRateGTexelsPerSecond = 1;
    PassEstimate e = estimate(work);
    EXPECT_DOUBLE_EQ(e.fetches, 1000);
    EXPECT_DOUBLE_EQ(e.fetchesMost, 4000);
    EXPECT_NEAR(e.fetchMs, 0.001, 1e-15);
    EXPECT_EQ(fetchesPerFragmentText(e, 1000), "1..4");

    work.fetchRuns = {{500, 3, 3, false}, {500, 2, 2, true}};
    e = estimate(work);
    EXPECT_TRUE(e.fetchesUnbounded);
    EXPECT_EQ(fetchesPerFragmentText(e, 1000), ">=2.5");
    EXPECT_EQ(fetchesPerFragmentText(e, 0), "-");
}
