// SLEPc (and with it PETSc and MPI) initialized once for a whole test program; include it in the
// test files that call SLEPc. gtest_main provides main().
#pragma once

#include <gtest/gtest.h>
#include <slepcsys.h>

namespace hpcontact::testing {

class SlepcEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { ASSERT_EQ(SlepcInitialize(nullptr, nullptr, nullptr, nullptr), 0); }
  void TearDown() override { SlepcFinalize(); }
};

[[maybe_unused]] inline ::testing::Environment* const slepc_environment =
    ::testing::AddGlobalTestEnvironment(new SlepcEnvironment);

}  // namespace hpcontact::testing
