// `roiclip run --config FILE`: a JSON object of options as command-line arguments.
#include <roiclip/batch/run.hpp>

#include <nlohmann/json.hpp>

namespace roiclip::batch {

std::vector<std::string> configToArguments(const std::string& jsonText, const std::string& source) {
  const nlohmann::json j = nlohmann::json::parse(jsonText, nullptr, false);
  if (j.is_discarded()) throw InvalidInputError(source + ": not valid JSON");
  if (!j.is_object()) throw InvalidInputError(source + ": expected a JSON object of options");
  std::vector<std::string> args;
  const auto scalar = [&](const std::string& key, const nlohmann::json& v) -> std::string {
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_integer()) return std::to_string(v.get<long long>());
    if (v.is_number()) return v.dump();
    throw InvalidInputError(source + ": option '" + key + "' must be a string, number or boolean");
  };
  for (const auto& [key, value] : j.items()) {
    const std::string flag = "--" + key;
    if (value.is_null()) continue;
    if (value.is_boolean()) {
      if (value.get<bool>()) args.push_back(flag);
    } else if (value.is_array()) {
      for (const auto& v : value) {
        args.push_back(flag);
        args.push_back(scalar(key, v));
      }
    } else {
      args.push_back(flag);
      args.push_back(scalar(key, value));
    }
  }
  return args;
}

}  // namespace roiclip::batch
