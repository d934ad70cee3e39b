// SPDX-License-Identifier: MIT
// `roiclip run --config FILE`: CLI11's config reader for JSON. The file is one object whose keys
// are the long option names without the dashes: {"roi": ["hull", "board:inspection"],
// "jobs": 2, "force": true}. CLI11 reads config files on the main app only, so the items go to
// the subcommand the reader was made for; options given on the command line win over the file.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace roiclip::app {

/// What a config file cannot say: not JSON, not an object, an unknown key, a value of the wrong
/// kind. The file's name is not known to the reader (CLI11 opens the file), so the message says
/// only the key and the problem; RunCommand prefixes the file.
class ConfigFileError : public CLI::ConfigError {
 public:
  /// @param key the offending key, empty for a problem of the whole file
  ConfigFileError(std::string key, std::string problem);
  [[nodiscard]] const std::string& key() const { return key_; }
  [[nodiscard]] const std::string& problem() const { return problem_; }

 private:
  std::string key_;
  std::string problem_;
};

/// CLI::Config for JSON files of one subcommand's options (set it on the main app with
/// App::config_formatter). Values: a string, a number, true/false (a flag on or off), an array
/// of those for an option that takes several (each element one occurrence), null (not given).
class ConfigJson : public CLI::Config {
 public:
  /// @param command the subcommand whose options the files hold; must outlive the reader.
  explicit ConfigJson(const CLI::App& command) : command_(command) {}

  /// The items of a JSON config, each under the command's name.
  /// @throws ConfigFileError for anything but an object of the command's configurable options
  ///         with values as above.
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override;

  /// The command's options as a JSON object in the same format: those given, and with
  /// `defaultAlso` the others that have a default.
  std::string to_config(const CLI::App* app, bool defaultAlso, bool writeDescription,
                        std::string prefix) const override;

 private:
  const CLI::App& command_;
};

}  // namespace roiclip::app
