// Unilateral contact law and the side bearing element built on it.
#include "contacts/UnilateralContact.h"

#include <gtest/gtest.h>

using namespace rockroll;

namespace {
const UnilateralContactLaw kLaw{1e8, 5.0};
}

TEST(UnilateralContactLaw, ZeroForceWhenOpen) {
    EXPECT_EQ(calcUnilateralNormalForce(-1e-3, 0.0, kLaw), 0.0);
    EXPECT_EQ(calcUnilateralNormalForce(-1e-3, 10.0, kLaw), 0.0);  // approaching but not touching
    EXPECT_EQ(calcUnilateralNormalForce(0.0, 10.0, kLaw), 0.0);
}

TEST(UnilateralContactLaw, ElasticForceIsStiffnessTimesPenetration) {
    for (double d : {1e-6, 1e-4, 2e-3}) EXPECT_DOUBLE_EQ(calcUnilateralNormalForce(d, 0.0, kLaw), 1e8 * d);
}

TEST(UnilateralContactLaw, DampingAddsOnApproachAndNeverPulls) {
    const double d = 1e-4;
    EXPECT_DOUBLE_EQ(calcUnilateralNormalForce(d, 0.1, kLaw), 1e8 * d * (1 + 5.0 * 0.1));
    EXPECT_LT(calcUnilateralNormalForce(d, -0.1, kLaw), 1e8 * d);
    // Fast separation: the damping term would make it negative; the law clamps at 0.
    EXPECT_EQ(calcUnilateralNormalForce(d, -1.0, kLaw), 0.0);
}

TEST(UnilateralContactLaw, ContinuousAtTouchdown) {
    EXPECT_NEAR(calcUnilateralNormalForce(1e-12, 2.0, kLaw), 0.0, 1e-2);  // 1e8·1e-12·11
}
