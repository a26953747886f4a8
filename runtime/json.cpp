#include "runtime/json.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>

namespace vbim::json {

namespace {

// Length of the well-formed UTF-8 sequence at s[i] (RFC 3629: no overlong forms, no surrogates,
// nothing above U+10FFFF), or 0 if the bytes there are not one.
std::size_t utf8SequenceAt(std::string_view s, std::size_t i) {
  const auto b = [&s](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char lead = b(i);
  std::size_t n = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (lead >= 0xC2 && lead <= 0xDF) {
    n = 2;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    n = 3;
    if (lead == 0xE0) lo = 0xA0;  // overlong
    if (lead == 0xED) hi = 0x9F;  // surrogates
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    n = 4;
    if (lead == 0xF0) lo = 0x90;  // overlong
    if (lead == 0xF4) hi = 0x8F;  // above U+10FFFF
  } else {
    return 0;
  }
  if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < n; ++k) {
    if (b(i + k) < 0x80 || b(i + k) > 0xBF) return 0;
  }
  return n;
}

}  // namespace

bool isUtf8(std::string_view s) {
  for (std::size_t i = 0; i < s.size();) {
    if (static_cast<unsigned char>(s[i]) < 0x80) {
      ++i;
      continue;
    }
    const std::size_t n = utf8SequenceAt(s, i);
    if (n == 0) return false;
    i += n;
  }
  return true;
}

std::string quote(std::string_view s) {
  static const char* const kHex = "0123456789abcdef";
  std::string out;
  out.reserve(s.size() + 2);
  out += '"';
  for (std::size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80) {
      // Text from a damaged file may be anything: well-formed UTF-8 is kept, any other byte becomes
      // U+FFFD, so the document stays valid JSON (RFC 8259 requires UTF-8).
      const std::size_t n = utf8SequenceAt(s, i);
      if (n == 0) {
        out += "\\ufffd";
      } else {
        out.append(s.substr(i, n));
        i += n - 1;
      }
      continue;
    }
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\b':
        out += "\\b";
        break;
      case '\f':
        out += "\\f";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (u < 0x20) {
          out += "\\u00";
          out += kHex[u >> 4];
          out += kHex[u & 15];
        } else {
          out += c;
        }
    }
  }
  out += '"';
  return out;
}

Value Value::decimal(std::string_view text) {
  // Split into sign, digits and the position of the decimal point relative to them.
  std::string_view t = text;
  const bool negative = !t.empty() && t[0] == '-';
  if (negative) t.remove_prefix(1);
  const std::size_t dot = t.find('.');
  if (t.empty() || t.find_first_not_of("0123456789.") != std::string_view::npos ||
      (dot != std::string_view::npos && t.find('.', dot + 1) != std::string_view::npos)) {
    throw std::invalid_argument("json::Value::decimal: not a plain decimal: " + std::string(text));
  }
  Value v(Kind::Number);
  if (dot == std::string_view::npos) {
    // An integer stays an integer.
    const std::size_t first = std::min(t.find_first_not_of('0'), t.size() - 1);
    v.text_ = (negative && t.substr(first) != "0" ? "-" : "") + std::string(t.substr(first));
    return v;
  }
  std::string digits = std::string(t.substr(0, dot)) + std::string(t.substr(dot + 1));
  int point = static_cast<int>(dot);  // digits[0 .. point) is the integer part
  const std::size_t lead = digits.find_first_not_of('0');
  if (lead == std::string::npos) {
    v.text_ = negative ? "-0.0" : "0.0";
    return v;
  }
  digits.erase(0, lead);
  point -= static_cast<int>(lead);
  digits.erase(digits.find_last_not_of('0') + 1);
  if (digits.size() > 15) throw std::invalid_argument("json::Value::decimal: more than 15 significant digits");
  // Layout of the shortest round-trip form: fixed notation for 1e-5 < |x| < 1e15, else an exponent.
  const int k = static_cast<int>(digits.size());
  const int n = point;
  std::string s = negative ? "-" : "";
  if (k <= n && n <= 15) {
    s += digits + std::string(static_cast<std::size_t>(n - k), '0') + ".0";
  } else if (0 < n && n <= 15) {
    s += digits.substr(0, static_cast<std::size_t>(n)) + "." + digits.substr(static_cast<std::size_t>(n));
  } else if (-4 < n && n <= 0) {
    s += "0." + std::string(static_cast<std::size_t>(-n), '0') + digits;
  } else {
    s += digits.substr(0, 1);
    if (k > 1) s += "." + digits.substr(1);
    const int e = n - 1;
    s += e < 0 ? "e-" : "e+";
    const std::string mag = std::to_string(e < 0 ? -e : e);
    s += (mag.size() < 2 ? "0" : "") + mag;
  }
  v.text_ = s;
  return v;
}

Value& Value::operator[](const std::string& key) {
  if (kind_ == Kind::Null) kind_ = Kind::Object;
  if (kind_ != Kind::Object) throw std::logic_error("json::Value: member of a non-object");
  for (std::size_t i = 0; i < keys_.size(); ++i) {
    if (keys_[i] == key) return items_[i];
  }
  keys_.push_back(key);
  items_.emplace_back();
  return items_.back();
}

void Value::push(Value v) {
  if (kind_ == Kind::Null) kind_ = Kind::Array;
  if (kind_ != Kind::Array) throw std::logic_error("json::Value: element of a non-array");
  items_.push_back(std::move(v));
}

std::string Value::dump(int indent) const {
  std::string out;
  write(out, indent, 0);
  return out;
}

void Value::write(std::string& out, int indent, int depth) const {
  const std::string inner(static_cast<std::size_t>(indent * (depth + 1)), ' ');
  const std::string outer(static_cast<std::size_t>(indent * depth), ' ');
  switch (kind_) {
    case Kind::Null:
      out += "null";
      return;
    case Kind::Boolean:
    case Kind::Number:
    case Kind::String:
      out += text_;
      return;
    case Kind::Array:
      if (items_.empty()) {
        out += "[]";
        return;
      }
      out += "[\n";
      for (std::size_t i = 0; i < items_.size(); ++i) {
        out += inner;
        items_[i].write(out, indent, depth + 1);
        out += i + 1 < items_.size() ? ",\n" : "\n";
      }
      out += outer + "]";
      return;
    case Kind::Object: {
      if (items_.empty()) {
        out += "{}";
        return;
      }
      std::vector<std::size_t> order(keys_.size());
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return keys_[a] < keys_[b]; });
      out += "{\n";
      for (std::size_t j = 0; j < order.size(); ++j) {
        out += inner + quote(keys_[order[j]]) + ": ";
        items_[order[j]].write(out, indent, depth + 1);
        out += j + 1 < order.size() ? ",\n" : "\n";
      }
      out += outer + "}";
      return;
    }
  }
}

Value object(const std::vector<std::pair<std::string, Value>>& members) {
  Value v = Value::object();
  for (const auto& [k, m] : members) v[k] = m;
  return v;
}

}  // namespace vbim::json
