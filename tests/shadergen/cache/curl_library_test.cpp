// libcurl is loaded on first use (src/cache/curl_library.h): the real library resolves every
// function the HTTP client calls, and a failed load says which library and why.
#include <gtest/gtest.h>

#include "cache/curl_library.h"

namespace {

TEST(CurlLibrary, LoadsLibcurlWithEveryFunctionTheClientCalls) {
  auto curl = shadergen::curl_library();
  ASSERT_TRUE(curl.ok()) << curl.errors().front().to_string();
  const shadergen::CurlLibrary& functions = **curl;
  EXPECT_NE(functions.easy_init, nullptr);
  EXPECT_NE(functions.easy_setopt, nullptr);
  EXPECT_NE(functions.easy_perform, nullptr);
  EXPECT_NE(functions.slist_free_all, nullptr);
  EXPECT_STREQ(functions.easy_strerror(CURLE_OK), "No error");
  EXPECT_EQ(shadergen::curl_library().value(), *curl) << "loaded once";
}

TEST(CurlLibrary, AMissingLibraryIsAnErrorNamingIt) {
  auto curl = shadergen::load_curl_library("libshadergen-no-such-curl.so.4");
  ASSERT_FALSE(curl.ok());
  const std::string message = curl.errors().front().to_string();
  EXPECT_EQ(message.rfind("error: cannot load libshadergen-no-such-curl.so.4 for the remote cache: ", 0), 0u)
      << message;
  EXPECT_NE(message.find("cannot open shared object file"), std::string::npos) << message;
}

TEST(CurlLibrary, ALibraryWithoutCurlIsAnErrorNamingTheMissingFunction) {
  auto curl = shadergen::load_curl_library("libm.so.6");
  ASSERT_FALSE(curl.ok());
  EXPECT_EQ(curl.errors().front().to_string(), "error: libm.so.6 has no curl_global_init");
}

}  // namespace
