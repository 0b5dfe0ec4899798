#include "formats/json_reader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <unordered_set>

#include "formats/nearest_name.h"

namespace shockmap {
namespace {

using Json = nlohmann::json;

// Where the parser is: one frame per open object or array, with the position in it.
class JsonPathTracker {
 public:
  explicit JsonPathTracker(std::string file) : file_(std::move(file)) {}

  // The parser's callback: throws InputError on too deep a nesting or a repeated key, keeps
  // every value otherwise.
  bool operator()(int /*depth*/, Json::parse_event_t event, Json& parsed) {
    using Event = Json::parse_event_t;
    switch (event) {
      case Event::object_start:
      case Event::array_start:
        Open(event == Event::object_start);
        break;
      case Event::object_end:
      case Event::array_end:
        frames_.pop_back();
        break;
      case Event::key:
        Key(parsed.get<std::string>());
        break;
      case Event::value:
        NextItem();
        break;
    }
    return true;
  }

  // The path of the value the parser reads next: the one it failed on, when it threw.
  std::string PathOfNextValue() const { return Path(1); }

 private:
  struct Frame {
    bool object = false;
    std::string key;       // The key being read (objects).
    long long index = -1;  // The item being read (arrays).
    std::unordered_set<std::string> keys;
  };

  void NextItem() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
  }

  void Open(bool object) {
    NextItem();
    if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
      FailAt(file_, Path(),
             "objects and arrays nested " + std::to_string(kMaxJsonDepth + 1) +
                 " levels deep; at most " + std::to_string(kMaxJsonDepth) + " levels are allowed");
    }
    frames_.push_back({object, {}, -1, {}});
  }

  void Key(const std::string& key) {
    Frame& f = frames_.back();
    f.key = key;
    if (!f.keys.insert(key).second)
      FailAt(file_, Path(), "key given twice in one object; each key may appear once");
  }

  // The path of the current position, e.g. zones[3].name, shortened for messages; the
  // innermost array's index advanced by `ahead` items.
  std::string Path(int ahead = 0) const {
    std::string path;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      const long long index = f.index + (i + 1 == frames_.size() ? ahead : 0);
      if (!f.object && index >= 0) path += "[" + std::to_string(index) + "]";
      if (f.object && !f.key.empty()) path += (path.empty() ? "" : ".") + Excerpt(f.key);
    }
    return path.size() > 80 ? path.substr(0, 77) + "..." : path;
  }

  std::string file_;
  std::vector<Frame> frames_;
};

bool IsControl(char c) {
  const auto u = static_cast<unsigned char>(c);
  return u < 0x20 || u == 0x7f;
}

// The library's message without its tag and without the text it quotes ("last read: '...'").
std::string SyntaxReason(const std::string& what) {
  const std::string reason = what.substr(what.find(']') + 2);
  return reason.substr(0, std::min(reason.find("; last read"), reason.find(" '")));
}

// Finds where the parser fails: a SAX pass that keeps nothing but the byte and the token of
// the first error.
class FailureLocator : public nlohmann::json_sax<Json> {
 public:
  bool null() override { return true; }
  bool boolean(bool) override { return true; }
  bool number_integer(number_integer_t) override { return true; }
  bool number_unsigned(number_unsigned_t) override { return true; }
  bool number_float(number_float_t, const string_t&) override { return true; }
  bool string(string_t&) override { return true; }
  bool binary(binary_t&) override { return true; }
  bool start_object(std::size_t) override { return true; }
  bool key(string_t&) override { return true; }
  bool end_object() override { return true; }
  bool start_array(std::size_t) override { return true; }
  bool end_array() override { return true; }
  bool parse_error(std::size_t byte, const std::string& token,
                   const nlohmann::detail::exception&) override {
    byte_ = byte;
    token_ = token;
    return false;
  }

  std::size_t byte_ = 0;  // Bytes read up to the end of the failing token.
  std::string token_;
};

// "line L" of the byte at `offset` in `text`, counted from 1.
std::string LineOf(const std::string& text, std::size_t offset) {
  const auto end = text.begin() + static_cast<std::ptrdiff_t>(std::min(offset, text.size()));
  return "line " + std::to_string(1 + std::count(text.begin(), end, '\n'));
}

// A number beyond a double's range (1e400, -1e400), named by its line, key path and digits.
[[noreturn]] void FailOnHugeNumber(const std::string& text, const std::string& file,
                                   const std::string& path) {
  FailureLocator locator;
  Json::sax_parse(text, &locator);
  const std::string line =
      LineOf(text, locator.byte_ - std::min(locator.byte_, locator.token_.size()));
  FailAt(file, path.empty() ? line : path + " (" + line + ")",
         "the number " + Excerpt(locator.token_) +
             " is beyond a double's range; numbers must be finite, at most about 1.8e308 in "
             "magnitude");
}

// A key of `object`, not among those `read`, near enough to `key` to be a misspelling of it.
std::optional<std::string> MisspellingOf(const std::string& key, const Json& object,
                                         const std::set<std::string>& read) {
  for (const auto& [given, value] : object.items()) {
    if (!read.contains(given) && NearestName(given, {key})) return given;
  }
  return std::nullopt;
}

}  // namespace

std::string Excerpt(const std::string& text, std::size_t offset) {
  constexpr std::size_t kMaxBytes = 40;
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  const std::size_t end = std::min(text.size(), offset + kMaxBytes);
  for (std::size_t i = offset; i < end; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      out += std::string("\\x") + kHex[c >> 4] + kHex[c & 15];
    }
  }
  if (end < text.size()) out += "...";
  return out;
}

nlohmann::json ParseJsonText(const std::string& text, const std::string& file) {
  JsonPathTracker tracker(file);
  try {
    return Json::parse(text, std::ref(tracker));
  } catch (const Json::out_of_range&) {  // A number beyond a double's range.
    FailOnHugeNumber(text, file, tracker.PathOfNextValue());
  } catch (const Json::parse_error& e) {
    const std::size_t at = e.byte > 0 ? std::min<std::size_t>(e.byte - 1, text.size()) : 0;
    throw InputError(file + ": not valid JSON (" + SyntaxReason(e.what()) + ", at byte " +
                     std::to_string(e.byte) + ": \"" + Excerpt(text, at) + "\")");
  }
}

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
  return ParseJsonText(text.str(), path);
}

std::string Shown(const nlohmann::json& value) {
  std::string s = value.dump();
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

const std::string& CheckedName(const std::string& name, const std::string& file,
                               const std::string& path) {
  if (std::any_of(name.begin(), name.end(), IsControl)) {
    FailAt(file, path,
           "name \"" + Excerpt(name) +
               "\" holds a control character (U+0000 to U+001F or U+007F); names may not");
  }
  return name;
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
  if (!Has(key)) {
    if (const auto given = MisspellingOf(key, object_, read_)) {
      FailAt(file_, PathOf(*given),
             "unknown key; did you mean \"" + key + "\"? (" + key + ": " + message + ")");
    }
  }
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

std::string JsonObjectReader::RequiredName(const std::string& key) {
  return CheckedName(RequiredString(key), file_, PathOf(key));
}

std::string JsonObjectReader::Text(const std::string& key, const std::string& fallback) {
  const std::string text = String(key, fallback);
  for (const char c : text) {
    if (IsControl(c) && c != '\t' && c != '\n' && c != '\r')
      Fail(key, "\"" + Excerpt(text) + "\" holds a control character other than tab or newline");
  }
  return text;
}

void JsonObjectReader::Finish() const {
  for (const auto& [key, value] : object_.items()) {
    if (!read_.contains(key)) {
      std::string known;
      for (const auto& k : read_) known += (known.empty() ? "" : ", ") + k;
      const auto meant = NearestName(key, {read_.begin(), read_.end()});
      Fail(key, "unknown key" + (meant ? "; did you mean \"" + *meant + "\"?" : std::string()) +
                    " (allowed here: " + known + ")");
    }
  }
}

}  // namespace shockmap
