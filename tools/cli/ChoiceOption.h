#pragma once
// An option that takes one word of a fixed list (--overlaps merge|keep|error): CLI11's
// CheckedTransformer reports a wrong word with its internal table ("Check foo value in
// {merge->0,...} OR {0,...} FAILED"); this one says "'foo' is not one of: merge, keep, error".
#include <CLI/CLI.hpp>

#include <string>
#include <utility>
#include <vector>

namespace aniso::cli {

/// Maps each word to its value (an enum or an integer: passed on as its number).
template <class T>
CLI::Validator choice(std::vector<std::pair<std::string, T>> words) {
  std::string names;
  for (const auto& [w, v] : words) names += (names.empty() ? "" : ", ") + w;
  return CLI::Validator(
      [words, names](std::string& in) -> std::string {
        for (const auto& [w, v] : words)  // the word, or the number it stands for (--msh-version 22)
          if (w == in || std::to_string(static_cast<long long>(v)) == in) {
            in = std::to_string(static_cast<long long>(v));
            return {};
          }
        return "'" + in + "' is not one of: " + names;
      },
      "", "choice");
}

}  // namespace aniso::cli
