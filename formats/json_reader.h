#pragma once
// Strict reading of JSON input files: every error names the file, the key path (e.g.
// grids[1].rk.logspace), the value found and what is allowed; unknown keys are errors.

#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "core/input_error.h"

namespace shockmap {

// Objects and arrays nested deeper than this are refused while parsing: no scene or study
// comes near it, and deeper documents would exhaust the stack of the recursive code that walks,
// copies and prints them.
inline constexpr int kMaxJsonDepth = 64;

// Parses `path` as JSON (see ParseJsonText); throws InputError naming the file (missing,
// unreadable, not a regular file, over 64 MiB).
nlohmann::json ReadJsonFile(const std::string& path);

// Parses `text`, read from `file` (named in messages), as JSON. Throws InputError naming the
// file and the key path for nesting deeper than kMaxJsonDepth and for a key given twice in one
// object; for a syntax error, naming the line, column and byte with an Excerpt() of the text
// there, never more of it.
nlohmann::json ParseJsonText(const std::string& text, const std::string& file);

// At most 40 bytes of `text` from `offset`, for messages: bytes outside printable ASCII (and the
// backslash) written as \xNN, "..." appended when more follows.
std::string Excerpt(const std::string& text, std::size_t offset = 0);

// One JSON object being read. Call Finish() once every known key has been read: it rejects the
// keys nobody asked for, naming the allowed key each most likely misspells.
class JsonObjectReader {
 public:
  JsonObjectReader(const nlohmann::json& value, std::string file, std::string path);

  bool Has(const std::string& key) const { return object_.contains(key); }
  // The raw value of a key (marking it read), or nullptr when absent.
  const nlohmann::json* Get(const std::string& key);
  // Path of a key of this object, for nested readers and messages.
  std::string PathOf(const std::string& key) const;

  double Number(const std::string& key, double fallback);
  double RequiredNumber(const std::string& key);
  int Integer(const std::string& key, int fallback);
  std::string String(const std::string& key, const std::string& fallback);
  std::string RequiredString(const std::string& key);
  // A required name without control characters (U+0000-U+001F, U+007F): names become
  // database keys, CSV columns and lines of output.
  std::string RequiredName(const std::string& key);
  // Free text: any characters but the control characters other than tab, CR and LF.
  std::string Text(const std::string& key, const std::string& fallback);
  void Finish() const;

  // Throws InputError "<file>: <path>: <message>". When `key` is absent (a required key
  // missing) and a key not read looks like a misspelling of it, that key is named instead:
  // "<file>: <path of the misspelt key>: unknown key; did you mean "<key>"? (<key>: <message>)".
  [[noreturn]] void Fail(const std::string& key, const std::string& message) const;
  const std::string& File() const { return file_; }

 private:
  const nlohmann::json& object_;
  std::string file_;
  std::string path_;
  std::set<std::string> read_;
};

// Throws InputError "<file>: <path>: <message>".
[[noreturn]] void FailAt(const std::string& file, const std::string& path,
                         const std::string& message);
// A finite number at `path`, or InputError.
double NumberAt(const nlohmann::json& value, const std::string& file, const std::string& path);
// The value as it appears in the file, shortened, for messages.
std::string Shown(const nlohmann::json& value);
// `name` when it holds no control character (U+0000-U+001F, U+007F), else InputError at `path`.
const std::string& CheckedName(const std::string& name, const std::string& file,
                               const std::string& path);

}  // namespace shockmap
