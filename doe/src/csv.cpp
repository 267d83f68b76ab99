#include "paddy/doe/csv.hpp"

#include "paddy/doe/error.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

namespace paddy::doe {

namespace {
std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}
}  // namespace

std::vector<std::string> splitCsvLine(const std::string& line, const std::string& where) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false, wasQuoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cur += '"', ++i;
      else if (c == '"') quoted = false;
      else cur += c;
    } else if (c == '"') {
      if (!wasQuoted && trim(cur).empty()) cur.clear();  // blanks before a quoted field
      quoted = wasQuoted = true;
    } else if (c == ',') {
      out.push_back(wasQuoted ? cur : trim(cur));
      cur.clear();
      wasQuoted = false;
    } else if (!(wasQuoted && (c == ' ' || c == '\t' || c == '\r'))) {  // blanks after one
      cur += c;
    }
  }
  if (quoted) throw DoeError(where + ": unterminated quoted field");
  out.push_back(wasQuoted ? cur : trim(cur));
  return out;
}

std::vector<std::string> splitList(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, sep))
    if (!trim(item).empty()) out.push_back(trim(item));
  return out;
}

Table parseCsv(const std::string& text, const std::string& source) {
  Table t;
  t.source = source;
  std::stringstream in(text);
  std::string line;
  int lineNo = 0;
  while (std::getline(in, line)) {
    ++lineNo;
    if (trim(line).empty()) continue;
    const std::string where = source + " line " + std::to_string(lineNo);
    auto fields = splitCsvLine(line, where);
    if (t.columns.empty()) {
      for (std::size_t j = 0; j < fields.size(); ++j) {
        if (fields[j].empty()) throw DoeError(where + ": header column " + std::to_string(j + 1) + " has no name");
        for (std::size_t i = 0; i < j; ++i)
          if (fields[i] == fields[j]) throw DoeError(where + ": duplicate column name '" + fields[j] + "'");
      }
      t.columns = fields;
      continue;
    }
    if (fields.size() != t.columns.size())
      throw DoeError(where + " (data row " + std::to_string(t.rows() + 1) + "): " + std::to_string(fields.size()) +
                     " fields but the header has " + std::to_string(t.columns.size()));
    t.cells.push_back(std::move(fields));
    t.lines.push_back(lineNo);
  }
  if (t.columns.empty()) throw DoeError(source + ": empty file (no header)");
  return t;
}

Table readCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw DoeError("cannot open '" + path + "' for reading");
  std::stringstream ss;
  ss << in.rdbuf();
  return parseCsv(ss.str(), path);
}

bool Table::hasColumn(const std::string& name) const {
  for (const auto& c : columns)
    if (c == name) return true;
  return false;
}

int Table::columnIndex(const std::string& name) const {
  for (std::size_t j = 0; j < columns.size(); ++j)
    if (columns[j] == name) return static_cast<int>(j);
  std::string avail;
  for (const auto& c : columns) avail += (avail.empty() ? "" : ", ") + c;
  throw DoeError(source + ": no column named '" + name + "' (available columns: " + avail + ")");
}

Eigen::VectorXd Table::numeric(const std::string& name) const {
  const int j = columnIndex(name);
  Eigen::VectorXd v(rows());
  for (int i = 0; i < rows(); ++i) {
    const std::string& cell = cells[i][j];
    const std::string where = source + ": row " + std::to_string(i + 1) + " (line " + std::to_string(lines[i]) +
                              "), column '" + name + "'";
    if (cell.empty()) throw DoeError(where + ": missing value");
    std::size_t pos = 0;
    double x = 0;
    try {
      x = std::stod(cell, &pos);
    } catch (...) {
      pos = 0;
    }
    if (pos != cell.size() || !std::isfinite(x)) throw DoeError(where + ": '" + cell + "' is not a finite number");
    v(i) = x;
  }
  return v;
}

std::string formatNumber(double v) {
  if (std::isnan(v)) return "";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

std::string toCsv(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows) {
  std::string s;
  auto line = [&](const std::vector<std::string>& f) {
    for (std::size_t j = 0; j < f.size(); ++j) s += (j ? "," : "") + f[j];
    s += "\n";
  };
  line(header);
  for (const auto& r : rows) line(r);
  return s;
}

void writeFileAtomic(const std::string& path, const std::string& content) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::random_device rd;
  const fs::path tmp = dir / ("." + target.filename().string() + ".tmp" + std::to_string(rd()));
  {
    std::ofstream out(tmp, std::ios::binary);
    if (!out) throw DoeError("cannot write '" + tmp.string() + "' (does the directory exist?)");
    out << content;
    out.flush();
    if (!out) throw DoeError("error writing '" + tmp.string() + "'");
  }
  std::error_code ec;
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw DoeError("cannot rename temporary file to '" + path + "'");
  }
}

}  // namespace paddy::doe
