#pragma once
// TEST_UNDER_ASAN is defined in AddressSanitizer builds, for tests whose measurements ASan
// changes by design (address-space limits, resident memory). GCC defines
// __SANITIZE_ADDRESS__; clang answers __has_feature(address_sanitizer).
#if defined(__SANITIZE_ADDRESS__)
#define TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TEST_UNDER_ASAN 1
#endif
#endif
