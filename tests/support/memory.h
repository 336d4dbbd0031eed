// Host memory of this process, for the tests that long runs do not grow it.
#pragma once

#include <catch2/catch.hpp>

#include <malloc.h>

#include <fstream>
#include <string>

namespace test {

// Whether this build has AddressSanitizer: its quarantine holds freed memory back for a while, so
// the resident set grows with any churn and the memory tests' bounds say nothing; they skip.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool k_address_sanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool k_address_sanitizer = true;
#else
inline constexpr bool k_address_sanitizer = false;
#endif
#else
inline constexpr bool k_address_sanitizer = false;
#endif

#define SKIP_UNDER_ADDRESS_SANITIZER()                                                    \
  do {                                                                                   \
    if (::test::k_address_sanitizer) {                                                   \
      WARN("skipped: AddressSanitizer's quarantine keeps freed memory, so no bound holds"); \
      return;                                                                            \
    }                                                                                    \
  } while (0)

// Resident set size in MiB, from /proc/self/status (Linux).
inline double resident_mib() {
  std::ifstream status("/proc/self/status");
  std::string key;
  while (status >> key) {
    if (key == "VmRSS:") {
      double kib = 0.0;
      status >> kib;
      return kib / 1024.0;
    }
    status.ignore(1 << 12, '\n');
  }
  FAIL("no VmRSS in /proc/self/status");
  return 0.0;
}

// Bytes the C heap has handed out and not taken back, in MiB (glibc's mallinfo2): exact where the
// resident set would hide growth inside pages an earlier test freed.
inline double heap_in_use_mib() { return double(mallinfo2().uordblks) / (1024.0 * 1024.0); }

}  // namespace test
