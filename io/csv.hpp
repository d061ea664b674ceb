// A tiny RFC 4180 CSV writer for the planners' summary (opens directly in QGIS and spreadsheets).
// Deterministic: numbers use fixed notation with a set precision, independent of the locale,
// so the same results give byte-identical files.
#pragma once
#include <concepts>
#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>

namespace mc::io {

enum class LineEnding { CRLF, LF };

struct CsvOptions {
  LineEnding line_ending = LineEnding::CRLF;  // RFC 4180 says CRLF; LF for Unix tools
  int precision = 6;                          // digits after the decimal point for doubles
};

// `s` as one CSV field: quoted iff it contains a comma, a double quote, CR or LF; inner double
// quotes doubled.
std::string csv_escape(std::string_view s);

// Fixed notation, `precision` digits after the point, "C" locale; "-0.000" is written "0.000";
// NaN and infinities give an empty string (an empty CSV field reads as NULL in QGIS).
std::string format_fixed(double v, int precision);

class CsvWriter {
 public:
  // `out` should be opened in binary mode so line endings are written as chosen.
  explicit CsvWriter(std::ostream& out, CsvOptions options = {});

  CsvWriter& field(std::string_view s);
  CsvWriter& field(const char* s) { return field(std::string_view(s)); }
  CsvWriter& field(const std::string& s) { return field(std::string_view(s)); }
  CsvWriter& field(double v) { return field(v, options_.precision); }
  CsvWriter& field(double v, int precision);
  CsvWriter& field(bool v) { return raw(v ? "true" : "false"); }
  template <std::integral T>
  requires(!std::same_as<T, bool> && !std::same_as<T, char>) CsvWriter& field(T v) {
    return raw(std::to_string(v));
  }
  CsvWriter& empty() { return raw({}); }

  // Ends the row. Every row must have as many fields as the first (RFC 4180 §2.4);
  // a mismatch throws std::logic_error, since it is a bug in the caller.
  void end_row();

  std::size_t rows() const { return rows_; }

 private:
  CsvWriter& raw(std::string_view text);

  std::ostream& out_;
  CsvOptions options_;
  std::size_t fields_in_row_ = 0;
  std::size_t fields_per_row_ = 0;  // set by the first row
  std::size_t rows_ = 0;
  bool first_field_empty_ = false;
};

}  // namespace mc::io
