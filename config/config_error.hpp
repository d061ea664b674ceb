// The one exception type of config/: every rejection names the key path it is about, so a user
// can find the offending line ("decompose.levels: must be strictly decreasing").
#pragma once
#include <stdexcept>
#include <string>

namespace mc {

class ConfigError : public std::runtime_error {
 public:
  // `where` is optional context appended to the message (e.g. "lod.yaml:12").
  ConfigError(std::string key, std::string reason, const std::string& where = {})
      : std::runtime_error(key + ": " + reason + (where.empty() ? "" : " (" + where + ")")),
        key_(std::move(key)),
        reason_(std::move(reason)) {}
  const std::string& key() const { return key_; }        // e.g. "decompose.levels"
  const std::string& reason() const { return reason_; }  // e.g. "must be strictly decreasing"

 private:
  std::string key_;
  std::string reason_;
};

}  // namespace mc
