// Exceptions of the io/ module. Only file-level failures throw; per-object problems are collected
// as text beside the data so that one bad building never stops a city.
#pragma once
#include <stdexcept>

namespace mc::io {

// The file cannot be read as a whole: cannot open, malformed top-level JSON, not CityJSON,
// unsupported version, malformed OFF/OBJ.
class ReadError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The output cannot be written (directory missing, disk full, ...).
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace mc::io
