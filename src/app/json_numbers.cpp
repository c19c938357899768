// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "app/json_numbers.hpp"

#include <cctype>
#include <charconv>
#include <system_error>

namespace armstudy::app {

std::string shortest_number(double v) {
  if (v == 0) return std::signbit(v) ? "-0.0" : "0.0";
  // shortest round-trip digits d.ddd and the decimal exponent
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, std::abs(v), std::chars_format::scientific);
  const std::string sci(buf, r.ptr);
  const size_t e = sci.find('e');
  std::string digits;
  for (size_t i = 0; i < e; ++i)
    if (sci[i] != '.') digits += sci[i];
  const int k = static_cast<int>(digits.size());
  const int n = std::stoi(sci.substr(e + 1)) + 1;  // decimal point after n digits
  // nlohmann-json's layout (its format_buffer with min_exp -4, max_exp 15)
  std::string out = v < 0 ? "-" : "";
  if (k <= n && n <= 15) {
    out += digits + std::string(n - k, '0') + ".0";
  } else if (0 < n && n <= 15) {
    out += digits.substr(0, n) + "." + digits.substr(n);
  } else if (-4 < n && n <= 0) {
    out += "0." + std::string(-n, '0') + digits;
  } else {
    out += digits.substr(0, 1) + (k > 1 ? "." + digits.substr(1) : "") + "e";
    const int x = n - 1;
    out += x < 0 ? "-" : "+";
    const std::string xs = std::to_string(x < 0 ? -x : x);
    out += (xs.size() < 2 ? "0" : "") + xs;
  }
  return out;
}

std::string results_text(const nlohmann::json& j) {
  const std::string in = j.dump(2);
  std::string out;
  out.reserve(in.size() + 1);
  size_t i = 0;
  while (i < in.size()) {
    const char c = in[i];
    if (c == '"') {
      // a string, copied as it is (escapes included)
      const size_t start = i++;
      while (i < in.size() && in[i] != '"') i += in[i] == '\\' ? 2 : 1;
      out.append(in, start, ++i - start);
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      // a number: floats (with '.' or an exponent) are rewritten, integers kept
      const size_t start = i;
      bool is_float = false;
      while (i < in.size() && (std::isdigit(static_cast<unsigned char>(in[i])) || in[i] == '-' ||
                               in[i] == '+' || in[i] == '.' || in[i] == 'e' || in[i] == 'E')) {
        is_float = is_float || in[i] == '.' || in[i] == 'e' || in[i] == 'E';
        ++i;
      }
      double v = 0;
      const auto r = std::from_chars(in.data() + start, in.data() + i, v);
      if (is_float && r.ec == std::errc() && r.ptr == in.data() + i)
        out += shortest_number(v);
      else
        out.append(in, start, i - start);
    } else {
      out += c;
      ++i;
    }
  }
  out += '\n';
  return out;
}

}  // namespace armstudy::app
