#include "json.h"

#include <charconv>
#include <cstdio>
#include <cstring>

#include "numbers.h"

namespace acutemesh::io {

// Describes the token at position `pos` for "found ...".
std::string JsonReader::found(size_t pos) const {
  if (pos >= s_.size()) return "end of text";
  const char ch = s_[pos];
  if (ch == '"') {
    size_t e = pos + 1;
    while (e < s_.size() && s_[e] != '"' && s_[e] != '\n' && e - pos < 40) {
      if (s_[e] == '\\' && e + 1 < s_.size()) ++e;
      ++e;
    }
    std::string_view t = s_.substr(pos, e - pos + (e < s_.size() && s_[e] == '"' ? 1 : 0));
    return "the string " + printable(t, 42);
  }
  if (ch == '{' || ch == '}' || ch == '[' || ch == ']' || ch == ',' || ch == ':')
    return std::string("'") + ch + "'";
  size_t e = pos;
  while (e < s_.size() && e - pos < 40) {
    const char d = s_[e];
    if (!((d >= '0' && d <= '9') || (d >= 'a' && d <= 'z') || (d >= 'A' && d <= 'Z') || d == '-' ||
          d == '+' || d == '.' || d == '_'))
      break;
    ++e;
  }
  if (e > pos) return quote(s_.substr(pos, e - pos));
  char buf[32];
  std::snprintf(buf, sizeof buf, "the byte 0x%02X", static_cast<unsigned char>(ch));
  return buf;
}

bool JsonReader::failAt(size_t pos, const std::string& expected) {
  return c_.fail(line_, "expected " + expected + ", found " + found(pos));
}

bool JsonReader::string(std::string& out, const char* expected) {
  ws();
  if (peek() != '"') return fail(expected);
  out.clear();
  const size_t start = p_;
  ++p_;
  const size_t n = s_.size();
  while (true) {
    if (p_ >= n) return failAt(start, "a closing '\"' of the string");
    const unsigned char ch = static_cast<unsigned char>(s_[p_]);
    if (ch == '"') {
      ++p_;
      return true;
    }
    if (ch < 0x20) {
      if (ch == '\n') return c_.fail(line_, "expected '\"' closing the string, found end of line");
      return c_.fail(line_, "expected a string character, found a control character");
    }
    if (ch != '\\') {
      out += static_cast<char>(ch);
      ++p_;
      continue;
    }
    if (p_ + 1 >= n) return failAt(start, "a closing '\"' of the string");
    if (!escape(out)) return false;
  }
}

// The escape at p_ (a backslash, and one more character at least) onto out.
bool JsonReader::escape(std::string& out) {
  const size_t n = s_.size();
  const char esc = s_[p_ + 1];
  p_ += 2;
  switch (esc) {
    case '"':
      out += '"';
      break;
    case '\\':
      out += '\\';
      break;
    case '/':
      out += '/';
      break;
    case 'b':
      out += '\b';
      break;
    case 'f':
      out += '\f';
      break;
    case 'n':
      out += '\n';
      break;
    case 'r':
      out += '\r';
      break;
    case 't':
      out += '\t';
      break;
    case 'u': {
      uint32_t cp;
      if (!hex4(cp)) return false;
      if (cp >= 0xD800 && cp <= 0xDBFF) {
        uint32_t lo;
        if (p_ + 1 >= n || s_[p_] != '\\' || s_[p_ + 1] != 'u')
          return c_.fail(line_,
                         "expected a low surrogate '\\uDC00'-'\\uDFFF' after a high "
                         "surrogate, found none");
        p_ += 2;
        if (!hex4(lo)) return false;
        if (lo < 0xDC00 || lo > 0xDFFF)
          return c_.fail(line_,
                         "expected a low surrogate '\\uDC00'-'\\uDFFF', found a "
                         "different escape");
        cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
      } else if (cp >= 0xDC00 && cp <= 0xDFFF) {
        return c_.fail(line_,
                       "expected a high surrogate before a low one, found a lone "
                       "low surrogate");
      }
      appendUtf8(out, cp);
      break;
    }
    default:
      return c_.fail(line_, std::string("expected an escape (\\\" \\\\ \\/ \\b \\f \\n \\r "
                                        "\\t \\uXXXX), found '\\") +
                                printable(std::string_view(&esc, 1)) + "'");
  }
  return true;
}

// Scans a JSON number at the current position without consuming it.
bool JsonReader::scanNumber(size_t& end, bool& integral) {
  const size_t n = s_.size();
  size_t q = p_;
  integral = true;
  if (q < n && s_[q] == '-') ++q;
  if (q >= n || !isDigit(s_[q])) return false;
  if (s_[q] == '0') {
    ++q;
  } else {
    while (q < n && isDigit(s_[q])) ++q;
  }
  if (q < n && s_[q] == '.') {
    integral = false;
    ++q;
    if (q >= n || !isDigit(s_[q])) return false;
    while (q < n && isDigit(s_[q])) ++q;
  }
  if (q < n && (s_[q] == 'e' || s_[q] == 'E')) {
    integral = false;
    ++q;
    if (q < n && (s_[q] == '+' || s_[q] == '-')) ++q;
    if (q >= n || !isDigit(s_[q])) return false;
    while (q < n && isDigit(s_[q])) ++q;
  }
  // A number runs into nothing but a delimiter: "1x" or "01" is not a number.
  if (q < n) {
    const char d = s_[q];
    if (!(d == ',' || d == ']' || d == '}' || d == ' ' || d == '\t' || d == '\n' || d == '\r'))
      return false;
  }
  end = q;
  return true;
}

bool JsonReader::number(double& v, const char* expected) {
  ws();
  size_t end;
  bool integral;
  if (!scanNumber(end, integral)) return fail(std::string(expected) + " (a number)");
  NumErr e = parseDecimal(s_.data() + p_, s_.data() + end, v);
  if (e == NumErr::OutOfRange) return fail(std::string(expected) + " within double range");
  if (e != NumErr::Ok) return fail(std::string(expected) + " (a number)");
  p_ = end;
  return true;
}

bool JsonReader::index(uint64_t& v, const char* expected) {
  ws();
  size_t end;
  bool integral;
  if (!scanNumber(end, integral) || !integral || s_[p_] == '-') return fail(expected);
  std::from_chars_result r = std::from_chars(s_.data() + p_, s_.data() + end, v);
  if (r.ec != std::errc() || v > kMaxIndexCount) return fail(expected);
  p_ = end;
  return true;
}

bool JsonReader::int32(int32_t& v, const char* expected) {
  ws();
  size_t end;
  bool integral;
  if (!scanNumber(end, integral) || !integral) return fail(expected);
  std::from_chars_result r = std::from_chars(s_.data() + p_, s_.data() + end, v);
  if (r.ec != std::errc() || r.ptr != s_.data() + end) return fail(expected);
  p_ = end;
  return true;
}

bool JsonReader::skipValue(int depth) {
  ws();
  if (depth > kMaxJsonDepth)
    return fail("nesting at most " + std::to_string(kMaxJsonDepth) + " deep");
  const char ch = peek();
  if (ch == '{') {
    ++p_;
    ws();
    if (peek() == '}') {
      ++p_;
      return true;
    }
    while (true) {
      if (!string(scratch_, "a key string") || !expect(':', "':' after the key") ||
          !skipValue(depth + 1))
        return false;
      ws();
      if (peek() == ',') {
        ++p_;
        continue;
      }
      if (peek() == '}') {
        ++p_;
        return true;
      }
      return fail("',' or '}'");
    }
  }
  if (ch == '[') {
    ++p_;
    ws();
    if (peek() == ']') {
      ++p_;
      return true;
    }
    while (true) {
      if (!skipValue(depth + 1)) return false;
      ws();
      if (peek() == ',') {
        ++p_;
        continue;
      }
      if (peek() == ']') {
        ++p_;
        return true;
      }
      return fail("',' or ']'");
    }
  }
  if (ch == '"') {
    return string(scratch_, "a value");
  }
  for (const char* word : {"true", "false", "null"}) {
    const size_t len = std::strlen(word);
    if (s_.substr(p_, len) == word) {
      size_t q = p_ + len;
      if (q < s_.size() && ((s_[q] >= 'a' && s_[q] <= 'z') || isDigit(s_[q])))
        return fail("a value");
      p_ = q;
      return true;
    }
  }
  size_t end;
  bool integral;
  if (scanNumber(end, integral)) {
    p_ = end;
    return true;
  }
  return fail("a value");
}

bool JsonReader::hex4(uint32_t& v) {
  v = 0;
  for (int i = 0; i < 4; ++i) {
    if (p_ >= s_.size())
      return c_.fail(line_, "expected 4 hex digits after '\\u', found end of text");
    const char h = s_[p_];
    uint32_t d;
    if (h >= '0' && h <= '9')
      d = static_cast<uint32_t>(h - '0');
    else if (h >= 'a' && h <= 'f')
      d = static_cast<uint32_t>(h - 'a' + 10);
    else if (h >= 'A' && h <= 'F')
      d = static_cast<uint32_t>(h - 'A' + 10);
    else
      return c_.fail(line_, "expected 4 hex digits after '\\u', found '" +
                                printable(std::string_view(&h, 1)) + "'");
    v = v * 16 + d;
    ++p_;
  }
  return true;
}

void JsonReader::appendUtf8(std::string& out, uint32_t cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

std::string_view s_;

}  // namespace acutemesh::io
