// A small JSON writer for the model's own outputs (trace.json, stats.json), so the portable model
// needs no JSON library. Output is byte-for-byte what the formatting conventions of the JSON
// library the tools around the model use (nlohmann::json's dump) would print for the same
// document: object keys in byte order, two-space indentation, strings escaped the same way, and
// decimals printed in the shortest form that reads back as the same double (tests/runtime/json_test
// checks both against that library).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace vbim::json {

// `s` as a JSON string literal with its quotes: ", \ and control characters escaped, well-formed
// UTF-8 as is, every byte that is not part of a well-formed UTF-8 sequence as \ufffd.
std::string quote(std::string_view s);
// True if `s` is well-formed UTF-8 (RFC 3629), so quote() replaces nothing in it.
bool isUtf8(std::string_view s);

class Value {
 public:
  Value() = default;  // null
  Value(bool b) : kind_(Kind::Boolean), text_(b ? "true" : "false") {}
  Value(int v) : Value(static_cast<std::int64_t>(v)) {}
  Value(long v) : kind_(Kind::Number), text_(std::to_string(v)) {}
  Value(long long v) : kind_(Kind::Number), text_(std::to_string(v)) {}
  Value(unsigned long v) : kind_(Kind::Number), text_(std::to_string(v)) {}
  Value(unsigned long long v) : kind_(Kind::Number), text_(std::to_string(v)) {}
  Value(const char* s) : kind_(Kind::String), text_(quote(s)) {}
  Value(const std::string& s) : kind_(Kind::String), text_(quote(s)) {}

  // A number given as exact decimal text ("12.500000", "0", "-3.25"), printed the way a double
  // parsed from it prints: "12.5", "0", "-3.25", "1.6e-05". At most 15 significant digits.
  static Value decimal(std::string_view text);
  static Value array() { return Value(Kind::Array); }
  static Value object() { return Value(Kind::Object); }

  // Object member (created, as null, when missing); turns a null value into an object.
  Value& operator[](const std::string& key);
  // Array element appended; turns a null value into an array.
  void push(Value v);

  // The document, indented by `indent` spaces per level (no trailing newline).
  std::string dump(int indent) const;

 private:
  enum class Kind { Null, Boolean, Number, String, Array, Object };
  explicit Value(Kind k) : kind_(k) {}
  void write(std::string& out, int indent, int depth) const;

  Kind kind_ = Kind::Null;
  std::string text_;  // scalars: their JSON text
  std::vector<std::string> keys_;
  std::vector<Value> items_;  // array elements, or object values in the order of keys_
};

// Builds an object from {key, value} pairs: json::object({{"a", 1}, {"b", true}}).
Value object(const std::vector<std::pair<std::string, Value>>& members);

}  // namespace vbim::json
