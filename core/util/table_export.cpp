// SPDX-License-Identifier: GPL-3.0-or-later
#include "util/table_export.h"

namespace bs {

std::string latex_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (text.compare(i, 2, "\xC2\xB1") == 0) {  // UTF-8 "±"
      out += "$\\pm$";
      ++i;
      continue;
    }
    switch (c) {
      case '&':
      case '%':
      case '$':
      case '#':
      case '_':
      case '{':
      case '}':
        out += '\\';
        out += c;
        break;
      case '~':
        out += "\\textasciitilde{}";
        break;
      case '^':
        out += "\\textasciicircum{}";
        break;
      case '\\':
        out += "\\textbackslash{}";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string to_latex(const ExportTable& t) {
  std::string align = t.align;
  if (align.empty()) {
    align = "l";
    for (std::size_t i = 1; i < t.header.size(); ++i) align += 'r';
  }
  const auto line = [](const std::vector<std::string>& cells) {
    std::string s = "    ";
    for (std::size_t i = 0; i < cells.size(); ++i) s += (i ? " & " : "") + latex_escape(cells[i]);
    return s + " \\\\\n";
  };
  std::string out = "% Written by BenchScope. Needs \\usepackage{booktabs}.\n\\begin{table}\n  \\centering\n";
  if (!t.caption.empty()) out += "  \\caption{" + latex_escape(t.caption) + "}\n";
  if (!t.label.empty()) out += "  \\label{" + t.label + "}\n";
  out += "  \\begin{tabular}{" + align + "}\n    \\toprule\n" + line(t.header) + "    \\midrule\n";
  for (const auto& r : t.rows) out += line(r);
  out += "    \\bottomrule\n  \\end{tabular}\n";
  if (!t.notes.empty()) {
    out += "  \\par\\smallskip\\footnotesize\n";
    for (const auto& n : t.notes) out += "  " + latex_escape(n) + "\\par\n";
  }
  out += "\\end{table}\n";
  return out;
}

std::string to_csv(const ExportTable& t) {
  const auto cell = [](const std::string& s) {
    if (s.find_first_of(",\"\r\n") == std::string::npos) return s;
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
  };
  const auto line = [&](const std::vector<std::string>& cells) {
    std::string s;
    for (std::size_t i = 0; i < cells.size(); ++i) s += (i ? "," : "") + cell(cells[i]);
    return s + "\r\n";
  };
  std::string out = line(t.header);
  for (const auto& r : t.rows) out += line(r);
  if (!t.notes.empty()) out += "\r\n";
  for (const auto& n : t.notes) out += line({n});
  return out;
}

}  // namespace bs
