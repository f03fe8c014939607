#pragma once
// Help and option errors written for people: a CLI11 formatter that shows each option's
// value as a word (H, N, FILE) with its default in the description, never the parser's
// internals (type names with validators, {false} flag defaults, transformer maps); and a
// "did you mean" for a misspelt option.
#include <CLI/CLI.hpp>

#include <string>

namespace aniso::cli {

class PeopleFormatter : public CLI::Formatter {
 public:
  PeopleFormatter() { column_width(34); }
  std::string make_option_name(const CLI::Option* opt, bool isPositional) const override;
  std::string make_option_opts(const CLI::Option* opt) const override;
  std::string make_option_desc(const CLI::Option* opt) const override;
};

/// The first argument of argv[1..argc) that looks like a long option ("--name" or
/// "--name=value") but is no option of `app` or of its subcommands, with the closest known
/// name (edit distance ≤ 2, less than half the name): "unknown option --hmaxx (did you mean
/// --hmax?)"; without a close name "unknown option --xyz". Empty when every option is known.
std::string unknownOptionMessage(const CLI::App& app, int argc, const char* const* argv);

/// Levenshtein distance of two strings (insertions, deletions, substitutions).
std::size_t editDistance(const std::string& a, const std::string& b);

}  // namespace aniso::cli
