// untrusted_text.h - text that came from outside the build (a remote cache's entries, an HTTP
// library's error message) made safe to print: one line, no terminal control sequences, a
// bounded length. A server that can write entries must not be able to rewrite a terminal.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace shadergen {

// `text` with every byte outside printable ASCII written as \n, \t, \\ or \xHH, cut after
// `max_bytes` input bytes with " ... (N more bytes)" appended.
std::string printable(std::string_view text, std::size_t max_bytes = 400);

// `url` with the user name and password (the "user:password@" before the host) replaced by
// "***@", so that a URL can be printed or written to a file.
std::string redacted_url(std::string_view url);

// `message` with every occurrence of the credentials of `url` (its "user:password" part, also
// the password alone) replaced by "***": for messages from libraries that may quote the URL.
std::string without_credentials(std::string message, std::string_view url);

}  // namespace shadergen
