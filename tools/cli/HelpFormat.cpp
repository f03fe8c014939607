#include "tools/cli/HelpFormat.h"

#include <algorithm>
#include <set>
#include <vector>

namespace aniso::cli {
namespace {

/// "a{false},b" -> "a,b": CLI11 lists a flag's default value in braces.
std::string withoutBraces(const std::string& s) {
  std::string out;
  int depth = 0;
  for (const char c : s) {
    if (c == '{') ++depth;
    else if (c == '}') depth = depth > 0 ? depth - 1 : 0;
    else if (depth == 0) out += c;
  }
  return out;
}

void collectNames(const CLI::App& app, std::set<std::string>& names) {
  for (const CLI::Option* o : app.get_options())
    for (const std::string& n : o->get_lnames()) names.insert(n);
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) collectNames(*sub, names);
}

}  // namespace

std::string PeopleFormatter::make_option_name(const CLI::Option* opt, bool isPositional) const {
  return withoutBraces(CLI::Formatter::make_option_name(opt, isPositional));
}

std::string PeopleFormatter::make_option_opts(const CLI::Option* opt) const {
  std::string out;
  if (!opt->get_option_text().empty()) {
    out = " " + opt->get_option_text();
  } else if (opt->get_type_size() != 0 && !opt->nonpositional()) {
    // a positional's name says it already
  } else if (opt->get_type_size() != 0) {
    const std::string type = opt->get_type_name();
    out = " " + type.substr(0, type.find(':'));
  }
  if (opt->get_required()) out += " (required)";
  return out;
}

std::string PeopleFormatter::make_option_desc(const CLI::Option* opt) const {
  std::string d = opt->get_description();
  if (opt->get_type_size() != 0 && !opt->get_default_str().empty()) d += " (default " + opt->get_default_str() + ")";
  return d;
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

std::string unknownOptionMessage(const CLI::App& app, int argc, const char* const* argv) {
  std::set<std::string> names;
  collectNames(app, names);
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--") break;  // the rest are positionals
    if (arg.size() < 3 || arg.compare(0, 2, "--") != 0) continue;
    const std::string name = arg.substr(2, arg.find('=') == std::string::npos ? std::string::npos : arg.find('=') - 2);
    if (names.count(name)) continue;
    std::string best;
    std::size_t bestDistance = 3;  // ≤ 2 edits
    for (const std::string& n : names) {
      const std::size_t d = editDistance(name, n);
      if (d < bestDistance && 2 * d < name.size()) {
        best = n;
        bestDistance = d;
      }
    }
    std::string msg = "unknown option --" + name;
    if (!best.empty()) msg += " (did you mean --" + best + "?)";
    return msg;
  }
  return {};
}

}  // namespace aniso::cli
