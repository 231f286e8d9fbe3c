// signed_entry.h - the signature a remote-cache entry carries when a team shares a secret.
//
// Anyone who can write to the server can otherwise store valid-looking SPIR-V under any key (the
// entry's own checksum is no defence: they recompute it). With a secret, every upload is the
// entry followed by a trailer, "SGHMAC1" and the 32-byte HMAC-SHA256 of the whole entry (magic,
// key, flags, text, checksum and words) under the secret; a reader holding the secret accepts
// only entries whose trailer matches. An entry moved to another key fails twice over: its key
// field differs from the requested key, and changing that field breaks the HMAC.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace shadergen {

// `entry` followed by its trailer under `secret` (not empty).
std::string signed_entry(std::string_view entry, std::string_view secret);

// The entry inside `body` when its trailer is the HMAC of the rest under `secret`; nullopt for
// unsigned bodies and wrong signatures. The comparison takes the same time wherever it differs.
std::optional<std::string_view> verified_entry(std::string_view body, std::string_view secret);

// The entry inside `body` with any trailer dropped, unchecked: for readers without the secret.
std::string_view unsigned_entry(std::string_view body);

}  // namespace shadergen
