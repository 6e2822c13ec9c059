#include "json.h"

#include <cstdint>

namespace trs {
namespace {

constexpr int kMaxDepth = 16;

class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  void skip_space() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t' ||
                                   text_[pos_] == '\n' || text_[pos_] == '\r')) {
      ++pos_;
    }
  }
  bool at_end() const { return pos_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[pos_]; }
  bool consume(char c) {
    if (peek() != c || at_end()) return false;
    ++pos_;
    return true;
  }

  // A string literal; its decoded UTF-8 goes to `out` (may be null).
  bool string(std::string* out) {
    if (!consume('"')) return false;
    while (!at_end()) {
      const char c = text_[pos_++];
      if (c == '"') return true;
      if (static_cast<uint8_t>(c) < 0x20) return false;
      if (c != '\\') {
        if (out) out->push_back(c);
        continue;
      }
      if (at_end()) return false;
      const char e = text_[pos_++];
      char plain = 0;
      switch (e) {
        case '"': plain = '"'; break;
        case '\\': plain = '\\'; break;
        case '/': plain = '/'; break;
        case 'b': plain = '\b'; break;
        case 'f': plain = '\f'; break;
        case 'n': plain = '\n'; break;
        case 'r': plain = '\r'; break;
        case 't': plain = '\t'; break;
        case 'u': {
          uint32_t code = 0;
          if (!hex4(&code)) return false;
          if (code >= 0xd800 && code <= 0xdbff) {
            uint32_t low = 0;
            if (!consume('\\') || !consume('u') || !hex4(&low) || low < 0xdc00 ||
                low > 0xdfff) {
              return false;
            }
            code = 0x10000 + ((code - 0xd800) << 10) + (low - 0xdc00);
          } else if (code >= 0xdc00 && code <= 0xdfff) {
            return false;
          }
          if (out) append_utf8(out, code);
          continue;
        }
        default: return false;
      }
      if (out) out->push_back(plain);
    }
    return false;
  }

  // Skips any value; `kind` (may be null) gets its JSON type name.
  bool value(int depth, const char** kind) {
    if (depth > kMaxDepth) return false;
    skip_space();
    const char c = peek();
    if (c == '"') {
      if (kind) *kind = "string";
      return string(nullptr);
    }
    if (c == '{') {
      if (kind) *kind = "object";
      return object(depth);
    }
    if (c == '[') {
      if (kind) *kind = "array";
      ++pos_;
      skip_space();
      if (consume(']')) return true;
      while (true) {
        if (!value(depth + 1, nullptr)) return false;
        skip_space();
        if (consume(']')) return true;
        if (!consume(',')) return false;
      }
    }
    if (c == 't' || c == 'f') {
      if (kind) *kind = "boolean";
      return word(c == 't' ? "true" : "false");
    }
    if (c == 'n') {
      if (kind) *kind = "null";
      return word("null");
    }
    if (kind) *kind = "number";
    return number();
  }

  // An object whose members are skipped.
  bool object(int depth) {
    if (!consume('{')) return false;
    skip_space();
    if (consume('}')) return true;
    while (true) {
      skip_space();
      if (!string(nullptr)) return false;
      skip_space();
      if (!consume(':')) return false;
      if (!value(depth + 1, nullptr)) return false;
      skip_space();
      if (consume('}')) return true;
      if (!consume(',')) return false;
    }
  }

  std::size_t pos() const { return pos_; }

 private:
  bool word(std::string_view w) {
    if (text_.substr(pos_, w.size()) != w) return false;
    pos_ += w.size();
    return true;
  }

  bool digits() {
    const std::size_t start = pos_;
    while (!at_end() && text_[pos_] >= '0' && text_[pos_] <= '9') ++pos_;
    return pos_ > start;
  }

  bool number() {
    consume('-');
    if (consume('0')) {
      // no leading zeros
    } else if (!digits()) {
      return false;
    }
    if (consume('.') && !digits()) return false;
    if (peek() == 'e' || peek() == 'E') {
      ++pos_;
      if (peek() == '+' || peek() == '-') ++pos_;
      if (!digits()) return false;
    }
    return true;
  }

  bool hex4(uint32_t* code) {
    if (pos_ + 4 > text_.size()) return false;
    uint32_t v = 0;
    for (int i = 0; i < 4; ++i) {
      const char h = text_[pos_++];
      v <<= 4;
      if (h >= '0' && h <= '9') {
        v |= static_cast<uint32_t>(h - '0');
      } else if (h >= 'a' && h <= 'f') {
        v |= static_cast<uint32_t>(h - 'a' + 10);
      } else if (h >= 'A' && h <= 'F') {
        v |= static_cast<uint32_t>(h - 'A' + 10);
      } else {
        return false;
      }
    }
    *code = v;
    return true;
  }

  static void append_utf8(std::string* out, uint32_t code) {
    if (code < 0x80) {
      out->push_back(static_cast<char>(code));
    } else if (code < 0x800) {
      out->push_back(static_cast<char>(0xc0 | (code >> 6)));
      out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
    } else if (code < 0x10000) {
      out->push_back(static_cast<char>(0xe0 | (code >> 12)));
      out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3f)));
      out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
    } else {
      out->push_back(static_cast<char>(0xf0 | (code >> 18)));
      out->push_back(static_cast<char>(0x80 | ((code >> 12) & 0x3f)));
      out->push_back(static_cast<char>(0x80 | ((code >> 6) & 0x3f)));
      out->push_back(static_cast<char>(0x80 | (code & 0x3f)));
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace

bool json_extract_cmd(std::string_view body, std::string* cmd, std::string* error) {
  const std::string expected = "body must be a JSON object like {\"cmd\": \"STATUS\"}";
  Scanner s(body);
  s.skip_space();
  if (!s.consume('{')) {
    *error = expected;
    return false;
  }
  bool found = false;
  s.skip_space();
  if (!s.consume('}')) {
    while (true) {
      s.skip_space();
      std::string key;
      if (!s.string(&key)) {
        *error = "malformed JSON at byte " + std::to_string(s.pos() + 1);
        return false;
      }
      s.skip_space();
      if (!s.consume(':')) {
        *error = "malformed JSON at byte " + std::to_string(s.pos() + 1);
        return false;
      }
      s.skip_space();
      if (key == "cmd") {
        if (s.peek() == '"') {
          cmd->clear();
          if (!s.string(cmd)) {
            *error = "malformed JSON string at byte " + std::to_string(s.pos() + 1);
            return false;
          }
          found = true;
        } else {
          const char* kind = "value";
          if (!s.value(1, &kind)) {
            *error = "malformed JSON at byte " + std::to_string(s.pos() + 1);
            return false;
          }
          *error = std::string("'cmd' must be a string (got ") + kind + ")";
          return false;
        }
      } else if (!s.value(1, nullptr)) {
        *error = "malformed JSON at byte " + std::to_string(s.pos() + 1);
        return false;
      }
      s.skip_space();
      if (s.consume('}')) break;
      if (!s.consume(',')) {
        *error = "malformed JSON at byte " + std::to_string(s.pos() + 1);
        return false;
      }
    }
  }
  s.skip_space();
  if (!s.at_end()) {
    *error = "unexpected data after the JSON object at byte " + std::to_string(s.pos() + 1);
    return false;
  }
  if (!found) {
    *error = "missing 'cmd': " + expected;
    return false;
  }
  return true;
}

std::string json_quote(std::string_view text) {
  static const char kHex[] = "0123456789abcdef";
  std::string out;
  out.reserve(text.size() + 2);
  out.push_back('"');
  for (char c : text) {
    const auto byte = static_cast<uint8_t>(c);
    if (c == '"' || c == '\\') {
      out.push_back('\\');
      out.push_back(c);
    } else if (byte < 0x20 || byte == 0x7f) {
      out += "\\u00";
      out.push_back(kHex[byte >> 4]);
      out.push_back(kHex[byte & 0xf]);
    } else {
      out.push_back(c);
    }
  }
  out.push_back('"');
  return out;
}

bool json_valid(std::string_view text) {
  Scanner s(text);
  if (!s.value(0, nullptr)) return false;
  s.skip_space();
  return s.at_end();
}

}  // namespace trs
