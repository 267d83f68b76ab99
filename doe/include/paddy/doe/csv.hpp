// Minimal CSV input/output for experiment tables and atomic file writing.
//
// Format: first line is the header; fields separated by commas; surrounding blanks ignored;
// double quotes may enclose a field ("" inside is a quote); blank lines skipped. Cells stay text
// until a column is requested as numbers, so descriptive columns (e.g. point type) are allowed.
// Errors name the file, the data row (1-based, header excluded), the line and the column.
// Atomic write: content goes to a temporary file in the target directory, then std::rename.
#pragma once
#include <Eigen/Dense>
#include <string>
#include <vector>

namespace paddy::doe {

struct Table {
  std::string source;                            ///< file name for messages
  std::vector<std::string> columns;
  std::vector<std::vector<std::string>> cells;   ///< rows x columns
  std::vector<int> lines;                        ///< source line of each row
  int rows() const { return static_cast<int>(cells.size()); }
  /// Index of a column; throws DoeError listing the available columns.
  int columnIndex(const std::string& name) const;
  bool hasColumn(const std::string& name) const;
  /// Column parsed as finite numbers; throws DoeError naming row and column of a bad cell.
  Eigen::VectorXd numeric(const std::string& name) const;
};

/// The fields of one CSV line (quotes and blanks as above); `where` names the line in the error
/// of an unterminated quoted field.
std::vector<std::string> splitCsvLine(const std::string& line, const std::string& where);
Table parseCsv(const std::string& text, const std::string& source = "<csv>");
Table readCsv(const std::string& path);

std::string formatNumber(double v);  ///< shortest round-trip-safe text (%.12g)
std::string toCsv(const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows);
void writeFileAtomic(const std::string& path, const std::string& content);
std::vector<std::string> splitList(const std::string& s, char sep = ',');

}  // namespace paddy::doe
