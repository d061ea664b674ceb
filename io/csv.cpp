#include "io/csv.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace mc::io {

std::string csv_escape(std::string_view s) {
  if (s.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(s);
  std::string out;
  out.reserve(s.size() + 2);
  out += '"';
  for (char c : s) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string format_fixed(double v, int precision) {
  if (!std::isfinite(v)) return {};
  if (precision < 0) precision = 0;
  char buf[400];  // |double| < 1.8e308: 309 integer digits + sign + point + up to ~80 decimals
  if (precision > 80) precision = 80;
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, precision);
  if (ec != std::errc()) throw std::runtime_error("format_fixed: buffer too small");
  std::string s(buf, end);
  // A negative value that rounds to zero ("-0.00") reads as an odd artefact in a spreadsheet.
  if (s[0] == '-' && s.find_first_not_of("-0.") == std::string::npos) s.erase(0, 1);
  return s;
}

CsvWriter::CsvWriter(std::ostream& out, CsvOptions options) : out_(out), options_(options) {}

CsvWriter& CsvWriter::field(std::string_view s) { return raw(csv_escape(s)); }

CsvWriter& CsvWriter::field(double v, int precision) { return raw(format_fixed(v, precision)); }

CsvWriter& CsvWriter::raw(std::string_view text) {
  if (fields_in_row_ > 0) out_ << ',';
  else first_field_empty_ = text.empty();
  out_ << text;
  ++fields_in_row_;
  return *this;
}

void CsvWriter::end_row() {
  if (rows_ == 0) {
    if (fields_in_row_ == 0) throw std::logic_error("CsvWriter: empty first row");
    fields_per_row_ = fields_in_row_;
  } else if (fields_in_row_ != fields_per_row_) {
    throw std::logic_error("CsvWriter: row " + std::to_string(rows_ + 1) + " has " +
                           std::to_string(fields_in_row_) + " fields, expected " +
                           std::to_string(fields_per_row_));
  }
  // A lone empty field would be a blank line, which readers skip: quote it instead.
  if (fields_in_row_ == 1 && first_field_empty_) out_ << "\"\"";
  out_ << (options_.line_ending == LineEnding::CRLF ? "\r\n" : "\n");
  fields_in_row_ = 0;
  ++rows_;
}

}  // namespace mc::io
