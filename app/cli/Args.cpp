#include "app/cli/Args.h"

#include <algorithm>
#include <charconv>
#include <cmath>

#include "app/cli/Text.h"

namespace armtrack::cli {

std::optional<double> parseDouble(std::string_view text) {
  if (text.size() > 1 && text[0] == '+' && text[1] != '-' && text[1] != '+') text.remove_prefix(1);
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() ||
      !std::isfinite(v)) {
    return std::nullopt;
  }
  return v;
}

Args::Args(std::string command, const std::vector<std::string>& args,
           const std::vector<OptionSpec>& specs)
    : m_command(std::move(command)) {
  if (std::any_of(args.begin(), args.end(),
                  [](const std::string& a) { return a == "--help" || a == "-h"; })) {
    m_help = true;
    return;
  }
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a.size() < 2 || a[0] != '-') {
      m_positionals.push_back(a);
      continue;
    }
    if (a[1] != '-') fail("unknown option '" + a + "'");
    const std::size_t eq = a.find('=');
    const std::string name = a.substr(0, eq);
    const auto spec = std::find_if(specs.begin(), specs.end(),
                                   [&](const OptionSpec& s) { return s.name == name; });
    if (spec == specs.end()) fail("unknown option '" + name + "'");
    if (!spec->takesValue) {
      if (eq != std::string::npos) fail(name + ": takes no value");
      m_values[name] = "";
      continue;
    }
    if (eq != std::string::npos) {
      m_values[name] = a.substr(eq + 1);
      m_all.emplace_back(name, m_values[name]);
    } else if (i + 1 < args.size() && !args[i + 1].starts_with("--")) {
      m_values[name] = args[++i];
      m_all.emplace_back(name, m_values[name]);
    } else {
      fail(name + ": missing value");
    }
  }
}

std::vector<std::string> Args::values(std::string_view name) const {
  std::vector<std::string> out;
  for (const auto& [n, v] : m_all)
    if (n == name) out.push_back(v);
  return out;
}

std::optional<std::string> Args::value(std::string_view name) const {
  const auto it = m_values.find(name);
  if (it == m_values.end()) return std::nullopt;
  return it->second;
}

std::optional<double> Args::number(std::string_view name) const {
  const auto text = value(name);
  if (!text) return std::nullopt;
  const auto v = parseDouble(*text);
  if (!v) fail(std::string(name) + ": expected a number, got " + inQuotes(*text));
  return v;
}

double Args::number(std::string_view name, double fallback) const {
  return number(name).value_or(fallback);
}

std::uint64_t Args::integer(std::string_view name, std::uint64_t fallback) const {
  const auto text = value(name);
  if (!text) return fallback;
  std::uint64_t v = 0;
  const char* end = text->data() + text->size();
  const auto r = std::from_chars(text->data(), end, v);
  if (text->empty() || r.ec != std::errc() || r.ptr != end) {
    fail(std::string(name) + ": expected a non-negative integer, got " + inQuotes(*text));
  }
  return v;
}

double Args::positive(std::string_view name, double fallback) const {
  const double v = number(name, fallback);
  if (!(v > 0.0)) fail(std::string(name) + ": must be > 0, got " + shortest(v));
  return v;
}

double Args::nonNegative(std::string_view name, double fallback) const {
  const double v = number(name, fallback);
  if (!(v >= 0.0)) fail(std::string(name) + ": must be >= 0, got " + shortest(v));
  return v;
}

std::string Args::single(std::string_view what) const {
  if (m_positionals.empty() || m_positionals[0].empty()) fail("missing " + std::string(what));
  if (m_positionals.size() > 1) fail("unexpected argument " + inQuotes(m_positionals[1]));
  return m_positionals[0];
}

std::string Args::required(std::string_view name) const {
  const auto v = value(name);
  if (!v) fail(std::string(name) + " is required");
  if (v->empty()) fail(std::string(name) + ": missing value");
  return *v;
}

}  // namespace armtrack::cli
