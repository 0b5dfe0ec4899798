#include "formats/json_reader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace shockmap {

nlohmann::json ReadJsonFile(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError(path + ": no such file");
  if (!std::filesystem::is_regular_file(status)) throw InputError(path + ": not a regular file");
  // Refused before reading: no scene or study comes near this; a device or a dump might.
  constexpr std::uintmax_t kMaxBytes = 64u << 20;
  if (std::filesystem::file_size(path, ec) > kMaxBytes) {
    throw InputError(path + ": larger than 64 MiB; not a scene or study file");
  }
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the file");
  std::stringstream text;
  text << in.rdbuf();
  if (text.str().find_first_not_of(" \t\r\n") == std::string::npos) {
    throw InputError(path + ": the file is empty; expected a JSON object");
  }
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& e) {  // Syntax errors and out-of-range numbers.
    throw InputError(path + ": not valid JSON (" + e.what() + ")");
  }
}

std::string Shown(const nlohmann::json& value) {
  std::string s = value.dump();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

void FailAt(const std::string& file, const std::string& path, const std::string& message) {
  throw InputError(file + ": " + (path.empty() ? "(top level)" : path) + ": " + message);
}

double NumberAt(const nlohmann::json& value, const std::string& file, const std::string& path) {
  if (!value.is_number()) FailAt(file, path, "expected a number, got " + Shown(value));
  const double v = value.get<double>();
  if (!std::isfinite(v)) FailAt(file, path, "expected a finite number, got " + Shown(value));
  return v;
}

JsonObjectReader::JsonObjectReader(const nlohmann::json& value, std::string file, std::string path)
    : object_(value), file_(std::move(file)), path_(std::move(path)) {
  if (!object_.is_object()) FailAt(file_, path_, "expected a JSON object, got " + Shown(object_));
}

std::string JsonObjectReader::PathOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

const nlohmann::json* JsonObjectReader::Get(const std::string& key) {
  read_.insert(key);
  const auto it = object_.find(key);
  return it == object_.end() ? nullptr : &*it;
}

void JsonObjectReader::Fail(const std::string& key, const std::string& message) const {
  FailAt(file_, PathOf(key), message);
}

double JsonObjectReader::Number(const std::string& key, double fallback) {
  const nlohmann::json* v = Get(key);
  return v == nullptr ? fallback : NumberAt(*v, file_, PathOf(key));
}

double JsonObjectReader::RequiredNumber(const std::string& key) {
  if (!Has(key)) Fail(key, "required number is missing");
  return Number(key, 0.0);
}

int JsonObjectReader::Integer(const std::string& key, int fallback) {
  const nlohmann::json* v = Get(key);
  if (v == nullptr) return fallback;
  if (!v->is_number_integer()) Fail(key, "expected an integer, got " + Shown(*v));
  const auto i = v->get<std::int64_t>();
  if (i < INT32_MIN || i > INT32_MAX) Fail(key, "integer out of range: " + Shown(*v));
  return static_cast<int>(i);
}

std::string JsonObjectReader::String(const std::string& key, const std::string& fallback) {
  const nlohmann::json* v = Get(key);
  if (v == nullptr) return fallback;
  if (!v->is_string()) Fail(key, "expected a string, got " + Shown(*v));
  return v->get<std::string>();
}

std::string JsonObjectReader::RequiredString(const std::string& key) {
  if (!Has(key)) Fail(key, "required string is missing");
  return String(key, "");
}

void JsonObjectReader::Finish() const {
  for (const auto& [key, value] : object_.items()) {
    if (!read_.contains(key)) {
      std::string known;
      for (const auto& k : read_) known += (known.empty() ? "" : ", ") + k;
      Fail(key, "unknown key (allowed here: " + known + ")");
    }
  }
}

}  // namespace shockmap
