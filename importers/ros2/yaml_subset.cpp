// SPDX-License-Identifier: GPL-3.0-or-later
#include "ros2/yaml_subset.h"

#include <cstdint>

namespace bs {
namespace {

struct Line {
  std::string text;  // without the line end
  std::size_t no = 0;
};

class Reader {
 public:
  Reader(std::vector<Line> lines, std::string file, std::size_t max_depth)
      : lines_(std::move(lines)), file_(std::move(file)), max_depth_(max_depth) {}

  YamlNode document() {
    skip_blank();
    if (at_end()) fail(ImportErrorCategory::MissingField, lines_.empty() ? 0 : lines_.back().no, "", "empty document");
    const std::size_t indent = indent_of(cur());
    YamlNode root = block(indent, 0);
    skip_blank();
    if (!at_end())
      fail(ImportErrorCategory::Syntax, cur().no, "", "text outside the document's structure (indentation?)");
    return root;
  }

 private:
  [[noreturn]] void fail(ImportErrorCategory c, std::size_t line, const std::string& field, const std::string& why) {
    throw ImportError(c, {file_, line, 0, field}, why);
  }
  bool at_end() const { return pos_ >= lines_.size(); }
  Line& cur() { return lines_[pos_]; }

  static bool blank_or_comment(const std::string& t) {
    const std::size_t f = t.find_first_not_of(' ');
    return f == std::string::npos || t[f] == '#';
  }
  void skip_blank() {
    while (!at_end() && blank_or_comment(cur().text)) ++pos_;
  }
  std::size_t indent_of(const Line& l) {
    std::size_t i = 0;
    while (i < l.text.size() && l.text[i] == ' ') ++i;
    if (i < l.text.size() && l.text[i] == '\t')
      fail(ImportErrorCategory::Unsupported, l.no, "", "a tab in indentation");
    return i;
  }
  static bool is_seq_item(std::string_view rest) { return rest == "-" || rest.starts_with("- "); }

  // A block (mapping or sequence) whose lines start at column `indent`.
  YamlNode block(std::size_t indent, std::size_t depth) {
    if (depth > max_depth_) fail(ImportErrorCategory::TooLarge, cur().no, "", "nested deeper than the limit");
    skip_blank();
    const std::string_view rest = std::string_view(cur().text).substr(indent);
    return is_seq_item(rest) ? sequence(indent, depth) : mapping(indent, depth);
  }

  YamlNode open_block(YamlNode::Kind kind) {
    YamlNode n;
    n.kind = kind;
    n.line = cur().no;
    return n;
  }
  // Whether the current line belongs to a block at `indent` (false: the block ended); deeper is an error.
  bool at_block_line(std::size_t indent, const char* what) {
    const std::size_t ind = indent_of(cur());
    if (ind > indent) fail(ImportErrorCategory::Syntax, cur().no, "", std::string("unexpected indentation in ") + what);
    return ind == indent;
  }

  YamlNode sequence(std::size_t indent, std::size_t depth) {
    YamlNode n = open_block(YamlNode::Kind::Seq);
    for (skip_blank(); !at_end(); skip_blank()) {
      if (!at_block_line(indent, "a sequence")) break;
      std::string_view rest = std::string_view(cur().text).substr(indent);
      if (!is_seq_item(rest)) break;
      if (rest == "-") {  // the item on the next, more-indented lines
        ++pos_;
        skip_blank();
        if (at_end() || indent_of(cur()) <= indent)
          fail(ImportErrorCategory::MissingField, lines_[pos_ - 1].no, "", "an empty sequence item");
        n.seq.push_back(block(indent_of(cur()), depth + 1));
        continue;
      }
      // "- key: value" or "- scalar": the item's text starts two columns in; the line is read as if the dash were
      // a space, so a mapping item continues on the lines indented like its first key.
      std::size_t content = indent + 2;
      while (content < cur().text.size() && cur().text[content] == ' ') ++content;
      cur().text.replace(indent, 1, " ");
      const std::string_view item = std::string_view(cur().text).substr(content);
      if (looks_like_key(item)) {
        n.seq.push_back(mapping(content, depth + 1));
      } else {
        const std::size_t no = cur().no;
        YamlNode s = scalar_at(content, indent, no);
        n.seq.push_back(std::move(s));
      }
    }
    return n;
  }

  // Whether `t` starts "key:" (a plain key followed by ": " or ":" at the end).
  static bool looks_like_key(std::string_view t) {
    if (t.empty() || t[0] == '"' || t[0] == '\'' || t[0] == '#') return false;
    for (std::size_t i = 0; i < t.size(); ++i) {
      if (t[i] == ':' && (i + 1 == t.size() || t[i + 1] == ' ')) return i > 0;
      if (t[i] == ' ' && i + 1 < t.size() && t[i + 1] == '#') return false;
    }
    return false;
  }

  YamlNode mapping(std::size_t indent, std::size_t depth) {
    YamlNode n = open_block(YamlNode::Kind::Map);
    for (skip_blank(); !at_end(); skip_blank()) {
      if (!at_block_line(indent, "a mapping")) break;
      const std::string_view t = std::string_view(cur().text).substr(indent);
      if (is_seq_item(t)) break;  // a sequence at the same indentation belongs to the parent key
      if (t == "---" && pos_ == 0) {
        ++pos_;
        continue;
      }
      if (t.starts_with("---") || t.starts_with("..."))
        fail(ImportErrorCategory::Unsupported, cur().no, "", "a second YAML document");
      if (!looks_like_key(t)) fail(ImportErrorCategory::Syntax, cur().no, "", "expected \"key: value\"");
      const std::size_t colon = t.find(':');
      const std::string key(t.substr(0, colon));
      for (char c : {'&', '*', '!', '[', '{', '?'})
        if (key.front() == c) fail(ImportErrorCategory::Unsupported, cur().no, key, "YAML feature not read here");
      const std::size_t key_line = cur().no;
      for (const auto& [k, v] : n.map)
        if (k == key)
          fail(ImportErrorCategory::InvalidValue, key_line, key,
               "duplicate key '" + key + "' (first at line " + std::to_string(v.line) + ")");
      std::size_t vstart = indent + colon + 1;
      while (vstart < cur().text.size() && cur().text[vstart] == ' ') ++vstart;
      YamlNode value;
      if (vstart >= cur().text.size() || cur().text[vstart] == '#') {
        ++pos_;
        skip_blank();
        if (!at_end() && (indent_of(cur()) > indent ||
                          (indent_of(cur()) == indent && is_seq_item(std::string_view(cur().text).substr(indent))))) {
          value = block(indent_of(cur()), depth + 1);
        } else {
          value.line = key_line;  // an empty value: null, kept as an empty scalar
        }
      } else {
        value = scalar_at(vstart, indent, key_line);
      }
      value.line = value.line ? value.line : key_line;
      if (value.kind == YamlNode::Kind::Scalar) value.line = key_line;
      n.map.push_back({key, std::move(value)});
    }
    return n;
  }

  // A scalar starting at column `col` of the current line; continuation lines must be indented more than
  // `parent_indent`. Leaves pos_ after its last line.
  YamlNode scalar_at(std::size_t col, std::size_t parent_indent, std::size_t line_no) {
    YamlNode s;
    s.line = line_no;
    const char q = cur().text[col];
    for (char c : {'&', '*', '!', '[', '{', '|', '>', '%', '@', '`'})
      if (q == c)
        fail(ImportErrorCategory::Unsupported, line_no, "", std::string("YAML feature '") + c + "' not read here");
    if (q == '\'' || q == '"') {
      s.quoted = true;
      s.scalar = quoted(col, q, parent_indent);
      return s;
    }
    std::string text = trim_comment(cur().text.substr(col));
    ++pos_;
    // Plain continuation: more-indented, non-blank lines that are not comments.
    while (!at_end()) {
      const std::string& t = cur().text;
      if (blank_or_comment(t)) {
        // A blank line inside a plain scalar is a newline only when the scalar goes on after it.
        std::size_t look = pos_;
        while (look < lines_.size() && blank_or_comment(lines_[look].text)) ++look;
        if (look < lines_.size() && indent_of(lines_[look]) > parent_indent && !blank_or_comment(lines_[look].text) &&
            !looks_like_key(std::string_view(lines_[look].text).substr(indent_of(lines_[look])))) {
          text += "\n";
          pos_ = look;
          continue;
        }
        break;
      }
      const std::size_t ind = indent_of(cur());
      if (ind <= parent_indent) break;
      const std::string_view body = std::string_view(t).substr(ind);
      if (looks_like_key(body))
        fail(ImportErrorCategory::Syntax, cur().no, "", "a key inside a plain scalar (indentation?)");
      if (!text.empty() && text.back() != '\n') text += ' ';
      text += trim_comment(std::string(body));
      ++pos_;
    }
    s.scalar = text;
    return s;
  }

  std::string trim_comment(std::string t) {
    for (std::size_t i = 0; i + 1 < t.size(); ++i)
      if (t[i] == ' ' && t[i + 1] == '#') {
        t.resize(i);
        break;
      }
    while (!t.empty() && t.back() == ' ') t.pop_back();
    return t;
  }

  static void append_utf8(std::string& out, std::uint32_t cp) {
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

  // A quoted scalar from column `col`, over as many lines as it takes; folds line breaks as YAML does.
  std::string quoted(std::size_t col, char q, std::size_t parent_indent) {
    const std::size_t start_line = cur().no;
    std::string out;
    std::size_t i = col + 1;
    bool joined = false;  // a double-quoted line ended in '\': the next line joins without a space
    for (;;) {
      const std::string& t = cur().text;
      while (i < t.size()) {
        const char c = t[i];
        if (c == q) {
          if (q == '\'' && i + 1 < t.size() && t[i + 1] == '\'') {
            out += '\'';
            i += 2;
            continue;
          }
          // The closing quote: only a comment may follow.
          const std::string after = trim_comment(t.substr(i + 1));
          if (!after.empty() && after.find_first_not_of(' ') != std::string::npos)
            fail(ImportErrorCategory::Syntax, cur().no, "", "text after a closing quote");
          ++pos_;
          return out;
        }
        if (q == '"' && c == '\\') {
          if (i + 1 == t.size()) {
            joined = true;
            ++i;
            break;
          }
          const char e = t[i + 1];
          i += 2;
          switch (e) {
            case '"':
              out += '"';
              break;
            case '\\':
              out += '\\';
              break;
            case '/':
              out += '/';
              break;
            case 'n':
              out += '\n';
              break;
            case 't':
              out += '\t';
              break;
            case 'r':
              out += '\r';
              break;
            case '0':
              out += '\0';
              break;
            case ' ':
              out += ' ';
              break;
            case 'x':
            case 'u':
            case 'U': {
              const std::size_t len = e == 'x' ? 2 : e == 'u' ? 4 : 8;
              if (i + len > t.size())
                fail(ImportErrorCategory::Syntax, cur().no, "", "a cut \\" + std::string(1, e) + " escape");
              std::uint32_t cp = 0;
              for (std::size_t k = 0; k < len; ++k) {
                const char h = t[i + k];
                const int d = h >= '0' && h <= '9'   ? h - '0'
                              : h >= 'a' && h <= 'f' ? h - 'a' + 10
                              : h >= 'A' && h <= 'F' ? h - 'A' + 10
                                                     : -1;
                if (d < 0)
                  fail(ImportErrorCategory::Syntax, cur().no, "",
                       "a bad hex digit in a \\" + std::string(1, e) + " escape");
                cp = cp * 16 + static_cast<std::uint32_t>(d);
              }
              if (cp > 0x10FFFF) fail(ImportErrorCategory::InvalidValue, cur().no, "", "an escape beyond Unicode");
              append_utf8(out, cp);
              i += len;
              break;
            }
            default:
              fail(ImportErrorCategory::Syntax, cur().no, "", std::string("unknown escape \\") + e);
          }
          continue;
        }
        out += c;
        ++i;
      }
      // The line ended inside the quotes: fold.
      if (!joined)
        while (!out.empty() && out.back() == ' ') out.pop_back();
      ++pos_;
      if (at_end()) fail(ImportErrorCategory::Syntax, start_line, "", "a quoted scalar is never closed");
      std::size_t empty = 0;
      while (!at_end() && cur().text.find_first_not_of(' ') == std::string::npos) {
        ++empty;
        ++pos_;
      }
      if (at_end()) fail(ImportErrorCategory::Syntax, start_line, "", "a quoted scalar is never closed");
      const std::size_t ind = indent_of(cur());
      if (ind <= parent_indent && cur().text[ind] != q)
        fail(ImportErrorCategory::Syntax, cur().no, "", "a quoted scalar's continuation is not indented");
      if (empty > 0)
        out += std::string(empty, '\n');
      else if (!joined)
        out += ' ';
      joined = false;
      i = ind;
    }
  }

  std::vector<Line> lines_;
  std::string file_;
  std::size_t max_depth_;
  std::size_t pos_ = 0;
};

}  // namespace

const YamlNode* YamlNode::find(std::string_view key) const {
  if (kind != Kind::Map) return nullptr;
  for (const auto& [k, v] : map)
    if (k == key) return &v;
  return nullptr;
}

YamlNode parse_yaml_subset(std::string_view text, const std::string& file, const ImportLimits& limits) {
  std::vector<Line> lines;
  std::size_t no = 0;
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    std::string l(text.substr(0, nl));
    text = nl == std::string_view::npos ? std::string_view{} : text.substr(nl + 1);
    if (!l.empty() && l.back() == '\r') l.pop_back();
    lines.push_back({std::move(l), ++no});
  }
  return Reader(std::move(lines), file, limits.max_json_depth).document();
}

}  // namespace bs
