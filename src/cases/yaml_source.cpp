// SPDX-License-Identifier: Apache-2.0
// Copyright 2026 The armstudy authors
#include "cases/yaml_source.hpp"

#include <cstdio>
#include <sstream>
#include <unordered_map>
#include <vector>

#include <yaml-cpp/eventhandler.h>

#include "cases/input_file.hpp"
#include "cases/yaml_reader.hpp"

namespace armstudy::cases {
namespace {

// a position in the text: line and column (1-based, columns in characters) as a yaml-cpp
// mark (0-based), so that Diagnostics formats it like every other error
YAML::Mark mark_at(int line, int column) {
  YAML::Mark m;
  m.line = line - 1;
  m.column = column - 1;
  m.pos = 0;
  return m;
}

// length of the UTF-8 sequence at s[i] and its code point, or 0 if it is not valid UTF-8
size_t decode_utf8(const std::string& s, size_t i, char32_t* cp) {
  const auto b = [&](size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char c = b(i);
  if (c < 0x80) {
    *cp = c;
    return 1;
  }
  size_t n = 0;
  char32_t v = 0, min = 0;
  if ((c & 0xE0) == 0xC0) {
    n = 2;
    v = c & 0x1F;
    min = 0x80;
  } else if ((c & 0xF0) == 0xE0) {
    n = 3;
    v = c & 0x0F;
    min = 0x800;
  } else if ((c & 0xF8) == 0xF0) {
    n = 4;
    v = c & 0x07;
    min = 0x10000;
  } else
    return 0;
  if (i + n > s.size()) return 0;
  for (size_t k = 1; k < n; ++k) {
    if ((b(i + k) & 0xC0) != 0x80) return 0;
    v = (v << 6) | (b(i + k) & 0x3F);
  }
  if (v < min || v > 0x10FFFF || (v >= 0xD800 && v <= 0xDFFF)) return 0;  // overlong, surrogate
  *cp = v;
  return n;
}

bool check_text(const std::string& s, Diagnostics& diag) {
  int line = 1, column = 1;
  size_t i = 0;
  if (s.compare(0, 3, "\xEF\xBB\xBF") == 0) i = 3;  // a UTF-8 byte order mark
  while (i < s.size()) {
    char32_t cp = 0;
    const size_t n = decode_utf8(s, i, &cp);
    if (n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(s[i]));
      diag.error(mark_at(line, column),
                 std::string("invalid UTF-8 (byte ") + hex + "); expected the file in UTF-8");
      return false;
    }
    if (cp == 0) {
      diag.error(mark_at(line, column),
                 "a NUL byte; expected text (is this a binary or UTF-16 file?)");
      return false;
    }
    if ((cp < 0x20 && cp != '\t' && cp != '\n' && cp != '\r') || cp == 0x7F ||
        (cp >= 0x80 && cp <= 0x9F && cp != 0x85)) {
      char hex[16];
      std::snprintf(hex, sizeof hex, "U+%04X", static_cast<unsigned>(cp));
      diag.error(mark_at(line, column), std::string("a control character (") + hex +
                                            "); expected printable text, tabs and line breaks");
      return false;
    }
    if (cp == '\n') {
      ++line;
      column = 1;
    } else
      ++column;
    i += n;
  }
  return true;
}

// characters that print as nothing or reorder the text around them: a name holding one
// would look like another in a message (zero-width spaces and joiners, direction marks and
// overrides, the byte order mark, the soft hyphen, invisible operators)
bool invisible(char32_t cp) {
  return cp == 0xAD || cp == 0x180E || (cp >= 0x200B && cp <= 0x200F) ||
         (cp >= 0x2028 && cp <= 0x202E) || (cp >= 0x2060 && cp <= 0x2069) || cp == 0xFEFF ||
         cp == 0x85 || (cp >= 0xFFF9 && cp <= 0xFFFB);
}

struct Refused {
  YAML::Mark mark;
  std::string message;
};

// walks the parser's events: depth, complex keys, alias recursion and expanded size
class StructureCheck : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark& mark) override { doc_mark_ = mark; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor, 1); }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string&) override {
    leaf(mark, anchor, 1);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    for (const Frame& f : stack_)
      if (f.anchor == anchor)
        throw Refused{mark,
                      "an alias (*) refers to a node that contains it (a recursive "
                      "alias); expected an alias to a complete node"};
    const auto it = sizes_.find(anchor);
    leaf(mark, 0, it == sizes_.end() ? 1 : it->second);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor, false);
  }
  void OnSequenceEnd() override { close(); }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor, true);
  }
  void OnMapEnd() override { close(); }

  const YAML::Mark& document_mark() const { return doc_mark_; }

 private:
  struct Frame {
    bool map = false;
    YAML::anchor_t anchor = 0;
    size_t size = 1;      // nodes of this subtree, aliases expanded
    size_t children = 0;  // in a map, even children are keys
  };

  // a node is about to be added to the top frame: is it a key of a mapping?
  void child(const YAML::Mark& mark, bool container) {
    if (stack_.empty()) return;
    Frame& top = stack_.back();
    if (top.map && top.children % 2 == 0 && container)
      throw Refused{mark,
                    "a key is a list or a mapping (a complex key); expected a plain key name"};
    ++top.children;
  }
  void add(const YAML::Mark& mark, size_t n) {
    total_ += n;
    if (total_ > kMaxNodes)
      throw Refused{mark, "the document has more than " + std::to_string(kMaxNodes) +
                              " nodes, counting each alias (*) as the nodes it repeats; "
                              "expected a case file of at most that size"};
  }
  void leaf(const YAML::Mark& mark, YAML::anchor_t anchor, size_t n) {
    child(mark, false);
    add(mark, n);
    if (!stack_.empty()) stack_.back().size += n;
    if (anchor) sizes_[anchor] = n;
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor, bool map) {
    child(mark, true);
    if (static_cast<int>(stack_.size()) >= kMaxDepth)
      throw Refused{mark, "lists and mappings nested more than " + std::to_string(kMaxDepth) +
                              " levels deep; expected a shallower file"};
    add(mark, 1);
    stack_.push_back({map, anchor, 1, 0});
  }
  void close() {
    const Frame f = stack_.back();
    stack_.pop_back();
    if (f.anchor) sizes_[f.anchor] = f.size;
    if (!stack_.empty()) stack_.back().size += f.size;
  }

  std::vector<Frame> stack_;
  std::unordered_map<YAML::anchor_t, size_t> sizes_;
  size_t total_ = 0;
  YAML::Mark doc_mark_;
};

}  // namespace

std::string brief(const std::string& s, size_t max_chars) {
  std::string out;
  size_t chars = 0, i = 0;
  for (; i < s.size() && chars < max_chars; ++chars) {
    const unsigned char c = static_cast<unsigned char>(s[i]);
    if (c == '\n') {
      out += "\\n";
      ++i;
      continue;
    }
    if (c == '\t') {
      out += "\\t";
      ++i;
      continue;
    }
    if (c < 0x20 || c == 0x7F) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
      ++i;
      continue;
    }
    char32_t cp = 0;
    const size_t n = decode_utf8(s, i, &cp);
    if (n == 0) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02X", c);
      out += hex;
      ++i;
      continue;
    }
    if (invisible(cp)) {
      char esc[16];
      std::snprintf(esc, sizeof esc, "\\u%04x", static_cast<unsigned>(cp));
      out += esc;
    } else {
      out.append(s, i, n);
    }
    i += n;
  }
  if (i < s.size()) out += "... (" + std::to_string(s.size()) + " bytes)";
  return out;
}

bool read_regular_file(const std::string& path, Diagnostics& diag, std::string* bytes) {
  std::string why;
  bool runtime = false;
  if (read_input_file(path, {kMaxFileBytes, "YAML file", true}, bytes, &why, &runtime)) return true;
  diag.error(YAML::Mark::null_mark(), why);
  return false;
}

bool check_yaml_source(const std::string& bytes, Diagnostics& diag) {
  if (!check_text(bytes, diag)) return false;
  std::istringstream in(bytes);
  YAML::Parser parser(in);
  StructureCheck check;
  try {
    if (!parser.HandleNextDocument(check)) return true;  // empty: the caller says so
    StructureCheck second;
    if (parser.HandleNextDocument(second)) {
      diag.error(second.document_mark(),
                 "a second YAML document (after '---' or '...'); expected one document per file");
      return false;
    }
  } catch (const Refused& r) {
    diag.error(r.mark, r.message);
    return false;
  } catch (const YAML::ParserException& e) {
    diag.error(e.mark, "not valid YAML (" + e.msg + "); expected a YAML mapping");
    return false;
  }
  return true;
}

}  // namespace armstudy::cases
