// Whether this test program is built instrumented (AddressSanitizer + UndefinedBehaviorSanitizer,
// `-DHPCONTACT_SANITIZE=ON`), where Eigen-heavy numerics run 10-20 times slower. Tests whose cost
// is a problem size, not a code path, stop at a smaller size there: every path still runs under
// the sanitizers, and the Release suite keeps the full sizes.
#pragma once

#ifndef HPCONTACT_SANITIZED
#define HPCONTACT_SANITIZED 0
#endif

namespace hpcontact::testing {

inline constexpr bool kInstrumented = HPCONTACT_SANITIZED != 0;

}  // namespace hpcontact::testing
