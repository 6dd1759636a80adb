// Engine test main: floating-point exceptions on, so a NaN or an overflow fails at its source
// (STYLE.md, Tests).
#include <cfenv>

#include <gtest/gtest.h>

int main(int argc, char** argv) {
    feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
