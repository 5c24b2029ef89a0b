// Minimal command-line option parsing for armtrack-cli: "--name value", "--name=value", flags and
// positional arguments, with the error messages the CLI prints.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace armtrack::cli {

/// A mistake in how the tool was called (exit code 2). command is "" for the top level.
class UsageError : public std::runtime_error {
 public:
  UsageError(std::string command, const std::string& message)
      : std::runtime_error(message), m_command(std::move(command)) {}
  const std::string& command() const { return m_command; }

 private:
  std::string m_command;
};

struct OptionSpec {
  std::string_view name;  ///< with the leading "--"
  bool takesValue;
};

class Args {
 public:
  /// Parses args (the words after the command name). Throws UsageError. When "--help" or "-h"
  /// appears anywhere, nothing else is checked and help() is true.
  Args(std::string command, const std::vector<std::string>& args,
       const std::vector<OptionSpec>& specs);

  bool help() const { return m_help; }
  bool flag(std::string_view name) const { return m_values.contains(std::string(name)); }
  /// The option's value (the last one given), if present.
  std::optional<std::string> value(std::string_view name) const;
  const std::vector<std::string>& positionals() const { return m_positionals; }
  /// Every value of a repeatable option, in the order given.
  std::vector<std::string> values(std::string_view name) const;

  /// The option as a finite number, or fallback when absent. Throws UsageError on bad text.
  std::optional<double> number(std::string_view name) const;
  double number(std::string_view name, double fallback) const;
  /// The option as a non-negative integer, or fallback when absent.
  std::uint64_t integer(std::string_view name, std::uint64_t fallback) const;

  /// The one positional argument; UsageError "missing <what>" when there is none (or it is
  /// empty), "unexpected argument '...'" when there are more.
  std::string single(std::string_view what) const;
  /// The option's value; UsageError when the option is absent or its value empty.
  std::string required(std::string_view name) const;

  /// Range checks: throw UsageError("--name: must be > 0, got 0").
  double positive(std::string_view name, double fallback) const;
  double nonNegative(std::string_view name, double fallback) const;

  [[noreturn]] void fail(const std::string& message) const { throw UsageError(m_command, message); }

 private:
  std::string m_command;
  bool m_help = false;
  std::map<std::string, std::string, std::less<>> m_values;  // flags map to ""
  std::vector<std::string> m_positionals;
  std::vector<std::pair<std::string, std::string>> m_all;  // every "--name value", in order
};

/// Parses a whole string as a finite decimal number (a leading '+' is accepted).
std::optional<double> parseDouble(std::string_view text);

}  // namespace armtrack::cli
