// Reports of `morphcut-city validate`, written while the file is read (nothing per object is
// kept): JSON, every object with its errors; text, one line per error of an invalid object.
#pragma once
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

#include "output/validate.hpp"

namespace mc::output {

nlohmann::json to_json(const ObjectReport& r);
nlohmann::json to_json(const ValidationCounts& c);

// {"file":..., "tolerances":{...}, "objects":[...], "counts":{...}, "file_problems":[...], "valid":...}
class JsonValidationWriter {
 public:
  JsonValidationWriter(std::ostream& out, const std::string& file, const ValidateOptions& opt);
  void object(const ObjectReport& r);
  void finish(const ValidationSummary& s);

 private:
  std::ostream& out_;
  bool first_ = true;
};

// "<id> (<type>): <code> <NAME>: <message>" per error.
void write_text_errors(std::ostream& out, const ObjectReport& r);
// Totals, with the share of valid parts; the last line says VALID or INVALID.
void write_text_summary(std::ostream& out, const ValidationSummary& s);

}  // namespace mc::output
