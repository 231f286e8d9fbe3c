// variants_file.h - the raw combinations a domain builds, read from a variants file.
//
// A domain of more than 2^20 raw IDs cannot be enumerated: it lists the combinations it uses,
// one per line, in the grammar of shadergen::parse_combination() (shadergen/registry.h), the
// same text `shadergen explain` and the generated find_raw_id() read:
//
//   # a material database's export; '#' starts a comment, blank lines are skipped
//   NORMAL_MAP | SHADOW_QUALITY=2
//   (none)
//
// A smaller domain may have one too: then only the listed IDs are built.
#pragma once

#include <filesystem>
#include <string>

#include "shadergen/diagnostic.h"
#include "shadergen/domain.h"

namespace shadergen {

// Settles which raw IDs `spec` builds. `override_path` (build --variants, relative to the
// working folder) replaces the spec's "variants_file" when not empty. With a variants file, its
// lines are read into spec.listed_raw_ids (ascending, each once; duplicate lines are allowed)
// and the SHA-256 of its bytes is returned, for the input-set key; without one, "" is returned.
//
// Errors: a missing or unreadable file (named where it was given: the spec's line, or
// "--variants"), more than kMaxVariantsLines lines, and per line, at FILE:LINE:COLUMN naming
// the word: anything parse_combination() refuses, and a combination an impossible rule prunes.
// At most kMaxSpecErrors lines are reported.
Result<std::string> read_variants_file(DomainSpec& spec, const std::filesystem::path& override_path = {});

}  // namespace shadergen
