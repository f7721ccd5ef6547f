// A JSON tokenizer over the whole text (strict RFC 8259 syntax, nesting depth limited),
// counting lines for messages. It reads values where the caller expects them, so each error
// names what was expected there.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "parse_context.h"

namespace acutemesh::io {

constexpr int kMaxJsonDepth = 200;

class JsonReader {
 public:
  JsonReader(std::string_view s, Ctx& c) : s_(s), c_(c) {
    if (s_.size() >= 3 && static_cast<unsigned char>(s_[0]) == 0xEF &&
        static_cast<unsigned char>(s_[1]) == 0xBB && static_cast<unsigned char>(s_[2]) == 0xBF)
      p_ = 3;  // UTF-8 byte order mark
  }

  size_t line() const { return line_; }
  Ctx& ctx() { return c_; }

  // Skips white space.
  void ws() {
    const size_t n = s_.size();
    while (p_ < n) {
      const char ch = s_[p_];
      if (ch == '\n') {
        ++line_;
        ++p_;
      } else if (ch == ' ' || ch == '\t' || ch == '\r') {
        ++p_;
      } else {
        break;
      }
    }
  }

  // After ws(): the next character, or 0 at the end.
  char peek() const { return p_ < s_.size() ? s_[p_] : '\0'; }
  bool atEnd() const { return p_ >= s_.size(); }
  void advance() { ++p_; }

  // "expected EXPECTED, found <the token here>" (or at `pos`); always false.
  bool fail(const std::string& expected) { return failAt(p_, expected); }
  bool failAt(size_t pos, const std::string& expected);

  bool expect(char ch, const char* expected) {
    ws();
    if (peek() == ch) {
      ++p_;
      return true;
    }
    return fail(expected);
  }
  // The same, with the expectation in pieces put together only on failure.
  bool expect(char ch, const char* a, const char* b, const char* c) {
    ws();
    if (peek() == ch) {
      ++p_;
      return true;
    }
    return fail(std::string(a) + b + c);
  }

  bool string(std::string& out, const char* expected);
  bool number(double& v, const char* expected);
  // A non-negative integer below 2^32 (vertex index or count).
  bool index(uint64_t& v, const char* expected);
  // An integer that fits 32 bits, signed (a boundary marker).
  bool int32(int32_t& v, const char* expected);
  // Parses and discards any value (validating it).
  bool skipValue(int depth);

  // Calls member(key, line) per member of an object, after its key and ':'; each key once.
  // `what` names the object for messages.
  template <class F>
  bool object(const std::string& what, F&& member) {
    if (!expect('{', ("'{' starting " + what).c_str())) return false;
    std::vector<std::string> seen;
    ws();
    if (peek() == '}') {
      ++p_;
      return true;
    }
    std::string key;
    while (true) {
      ws();
      const size_t keyLine = line_;
      if (!string(key, "a key string")) return false;
      for (const std::string& k : seen)
        if (k == key) return c_.fail(keyLine, "expected each key once, found \"" + printable(key) + "\" again");
      seen.push_back(key);
      if (!expect(':', "':' after the key") || !member(key, keyLine)) return false;
      ws();
      if (peek() == ',') {
        ++p_;
        continue;
      }
      if (peek() == '}') {
        ++p_;
        return true;
      }
      return fail("',' or '}' in " + what);
    }
  }

  // Calls elem() per element of an array; `what` names the array for messages.
  template <class F>
  bool array(const char* what, F&& elem) {
    ws();
    if (peek() != '[') return fail(std::string("'[' starting ") + what);
    ++p_;
    ws();
    if (peek() == ']') {
      ++p_;
      return true;
    }
    while (true) {
      if (!elem()) return false;
      ws();
      const char ch = peek();
      if (ch == ',') {
        ++p_;
        continue;
      }
      if (ch == ']') {
        ++p_;
        return true;
      }
      return fail(std::string("',' or ']' in ") + what);
    }
  }

 private:
  std::string found(size_t pos) const;
  bool scanNumber(size_t& end, bool& integral);
  bool escape(std::string& out);
  bool hex4(uint32_t& v);
  static void appendUtf8(std::string& out, uint32_t cp);

  std::string_view s_;
  Ctx& c_;
  size_t p_ = 0;
  size_t line_ = 1;
  std::string scratch_;  // strings skipped, kept out of skipValue's recursive frames
};

}  // namespace acutemesh::io
