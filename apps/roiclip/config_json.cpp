// SPDX-License-Identifier: MIT
// CLI11's config reader for JSON: one object of option names and values.
#include "config_json.hpp"

#include <cmath>
#include <istream>

#include <nlohmann/json.hpp>

namespace roiclip::app {

namespace {

using nlohmann::json;

std::string describe(const std::string& key, const std::string& problem) {
  return key.empty() ? problem : "'" + key + "': " + problem;
}

// The option a key names, looked up as CLI11's config parser does: "--key", then "-k" for a
// one-letter key, then a positional called "key".
const CLI::Option* optionFor(const CLI::App& command, const std::string& key) {
  if (key.empty()) return nullptr;
  const CLI::Option* option = command.get_option_no_throw("--" + key);
  if (option == nullptr && key.size() == 1) option = command.get_option_no_throw("-" + key);
  if (option == nullptr) option = command.get_option_no_throw(key);
  return option;
}

bool isFlag(const CLI::Option& option) { return option.get_expected_max() == 0; }

// A string or a number as the text the command line would have held.
std::string scalarText(const std::string& key, const json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_unsigned()) return std::to_string(value.get<unsigned long long>());
  if (value.is_number_integer()) return std::to_string(value.get<long long>());
  if (value.is_number()) {
    // 1e3 or 2.0 for an integer option reads as an integer; others keep the shortest text that
    // reads back the same double.
    const double v = value.get<double>();
    if (std::trunc(v) == v && std::fabs(v) < 9007199254740992.0) {
      return std::to_string(static_cast<long long>(v));
    }
    return value.dump();
  }
  throw ConfigFileError(key, "must be a string or a number");
}

}  // namespace

ConfigFileError::ConfigFileError(std::string key, std::string problem)
    : CLI::ConfigError(describe(key, problem)),
      key_(std::move(key)),
      problem_(std::move(problem)) {}

std::vector<CLI::ConfigItem> ConfigJson::from_config(std::istream& input) const {
  json root;
  try {
    root = json::parse(input);
  } catch (const json::parse_error& e) {
    throw ConfigFileError({}, "not valid JSON (at byte " + std::to_string(e.byte) + ")");
  } catch (const json::out_of_range&) {  // the one other error parsing gives
    throw ConfigFileError({}, "not valid JSON (a number out of range)");
  }
  if (!root.is_object()) throw ConfigFileError({}, "expected a JSON object of options");

  std::vector<CLI::ConfigItem> found;
  for (const auto& [key, value] : root.items()) {
    const CLI::Option* option = optionFor(command_, key);
    if (option == nullptr)
      throw ConfigFileError(key, "no such option of `" + command_.get_name() + "`");
    if (!option->get_configurable()) throw ConfigFileError(key, "cannot be set in a config file");
    if (value.is_null()) continue;
    CLI::ConfigItem item;
    item.parents = {command_.get_name()};
    item.name = key;
    if (isFlag(*option)) {
      if (!value.is_boolean()) throw ConfigFileError(key, "takes true or false (a flag)");
      item.inputs = {value.get<bool>() ? "true" : "false"};
    } else if (value.is_array()) {
      if (option->get_items_expected_max() <= 1) {
        throw ConfigFileError(key, "takes one value, not an array");
      }
      for (const json& element : value) item.inputs.push_back(scalarText(key, element));
    } else {
      item.inputs = {scalarText(key, value)};
    }
    found.push_back(std::move(item));
  }
  return found;
}

std::string ConfigJson::to_config(const CLI::App* /*app*/, bool defaultAlso,
                                  bool /*writeDescription*/, std::string /*prefix*/) const {
  json root = json::object();
  for (const CLI::Option* option : command_.get_options()) {
    if (!option->get_configurable()) continue;
    const std::string key =
        option->get_lnames().empty() ? option->get_name() : option->get_lnames().front();
    if (key.empty()) continue;
    if (isFlag(*option)) {
      if (option->count() > 0) root[key] = option->as<bool>();
      continue;
    }
    const bool several = option->get_items_expected_max() > 1;
    if (option->count() > 0) {
      root[key] = several ? json(option->results()) : json(option->results().back());
    } else if (defaultAlso && !several && !option->get_default_str().empty()) {
      root[key] = option->get_default_str();
    }
  }
  return root.dump(2, ' ', false, json::error_handler_t::replace) + "\n";
}

}  // namespace roiclip::app
