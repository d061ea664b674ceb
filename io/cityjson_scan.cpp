#include "io/cityjson_scan.hpp"

#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <istream>
#include <limits>
#include <streambuf>

#include "io/cityjson_common.hpp"
#include "io/errors.hpp"

namespace mc::io {

namespace {

using nlohmann::json;

// A read-only streambuf over a file descriptor that knows its byte position, so the SAX events
// can record where each CityObject starts and ends (nlohmann's SAX gives no positions).
class PositionedBuf : public std::streambuf {
 public:
  explicit PositionedBuf(int fd) : fd_(fd), buf_(1 << 20) { setg(buf_.data(), buf_.data(), buf_.data()); }
  uint64_t position() const { return base_ + static_cast<uint64_t>(gptr() - eback()); }
  bool io_error() const { return io_error_; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    base_ += static_cast<uint64_t>(egptr() - eback());
    ssize_t n;
    do n = ::read(fd_, buf_.data(), buf_.size());
    while (n < 0 && errno == EINTR);
    if (n <= 0) {
      io_error_ = n < 0;
      setg(buf_.data(), buf_.data(), buf_.data());
      return traits_type::eof();
    }
    setg(buf_.data(), buf_.data(), buf_.data() + n);
    return traits_type::to_int_type(*gptr());
  }

 private:
  int fd_;
  std::vector<char> buf_;
  uint64_t base_ = 0;
  bool io_error_ = false;
};

// Builds a json value from SAX events (like nlohmann's internal DOM parser), for the few parts
// of the file we keep: root members and the type/parents/children of each object.
class DomBuilder {
 public:
  bool active() const { return active_; }
  void begin(json* target) {
    target_ = target;
    stack_.clear();
    active_ = true;
  }
  void key(std::string k) { key_ = std::move(k); }
  void put(json v) {
    if (stack_.empty()) {
      *target_ = std::move(v);
      active_ = false;
    } else if (stack_.back()->is_array()) {
      stack_.back()->push_back(std::move(v));
    } else {
      (*stack_.back())[key_] = std::move(v);
    }
  }
  void open(json container) {
    json* slot;
    if (stack_.empty()) {
      *target_ = std::move(container);
      slot = target_;
    } else if (stack_.back()->is_array()) {
      stack_.back()->push_back(std::move(container));
      slot = &stack_.back()->back();
    } else {
      slot = &((*stack_.back())[key_] = std::move(container));
    }
    stack_.push_back(slot);
  }
  void close() {
    stack_.pop_back();
    if (stack_.empty()) active_ = false;
  }

 private:
  json* target_ = nullptr;
  std::vector<json*> stack_;
  std::string key_;
  bool active_ = false;
};

class Scanner {
 public:
  Scanner(PositionedBuf& buf, ScratchFile& spill, DocumentIndex& out)
      : buf_(buf), spill_(spill), out_(out), vlog_(out.problems, 20) {}

  std::string fatal;  // set when we stop the parse ourselves

  // ---- nlohmann SAX interface ----
  bool null() { return scalar(json(nullptr), false, 0); }
  bool boolean(bool v) { return scalar(json(v), false, 0); }
  bool number_integer(json::number_integer_t v) { return number(static_cast<double>(v), json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return number(static_cast<double>(v), json(v)); }
  bool number_float(json::number_float_t v, const std::string&) { return number(v, json(v)); }
  bool string(std::string& v) { return scalar(json(std::move(v)), false, 0); }
  bool binary(json::binary_t&) { return scalar(json(nullptr), false, 0); }
  bool start_object(std::size_t) { return open(true); }
  bool start_array(std::size_t) { return open(false); }
  bool end_object() { return close(true); }
  bool end_array() { return close(false); }
  bool key(std::string& k) {
    if (dom_.active()) {
      dom_.key(std::move(k));
    } else if (depth_ == 1) {
      member_key_ = std::move(k);
    } else if (member_ == Member::CityObjects && depth_ == 2) {
      object_id_ = std::move(k);
    } else if (member_ == Member::CityObjects && depth_ == 3 && object_ok_ &&
               (k == "parents" || k == "children")) {
      dom_.begin(&links_[k]);
    }
    return true;
  }
  bool parse_error(std::size_t position, const std::string&, const nlohmann::detail::exception& ex) {
    std::string what = ex.what();
    // Drop nlohmann's "[json.exception.parse_error.101] " prefix: users need the reason, not the code.
    if (auto p = what.find("] "); p != std::string::npos && what[0] == '[') what = what.substr(p + 2);
    fatal = "malformed JSON at byte " + std::to_string(position) + ": " + what;
    return false;
  }

  void finish() { vlog_.finish(); }

 private:
  enum class Member { None, CityObjects, Vertices, Other };

  bool number(double d, json&& v) {
    if (!dom_.active() && member_ == Member::Vertices) return vertex_component(d);
    return scalar(std::move(v), true, d);
  }

  bool scalar(json&& v, bool is_number, double d) {
    if (dom_.active()) {
      dom_.put(std::move(v));
      return true;
    }
    if (depth_ == 0) return stop("the top-level JSON value is not an object");
    if (depth_ == 1) {
      if (member_key_ == "CityObjects") return stop("\"CityObjects\" must be an object, got " + v.dump());
      if (member_key_ == "vertices") return stop("\"vertices\" must be an array, got " + v.dump());
      out_.root[member_key_] = std::move(v);
      return true;
    }
    if (member_ == Member::Vertices) {
      if (is_number) return vertex_component(d);
      vertex_bad_ = true;
      if (depth_ == 2) end_vertex();  // a bare non-array entry is one bad vertex
      return true;
    }
    if (member_ == Member::CityObjects && depth_ == 2)
      out_.problems.push_back("CityObject \"" + object_id_ + "\" is not a JSON object (" + v.dump() +
                              "); skipped");
    return true;
  }

  bool open(bool is_object) {
    if (depth_ >= kMaxJsonDepth)
      return stop("JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels at byte " +
                  std::to_string(buf_.position()));
    if (dom_.active()) {
      dom_.open(is_object ? json::object() : json::array());
      ++depth_;
      return true;
    }
    ++depth_;
    if (depth_ == 1) return is_object ? true : stop("the top-level JSON value is not an object");
    if (depth_ == 2) {
      if (member_key_ == "CityObjects") {
        if (!is_object) return stop("\"CityObjects\" must be an object, got an array");
        member_ = Member::CityObjects;
        out_.has_city_objects = true;
      } else if (member_key_ == "vertices") {
        if (is_object) return stop("\"vertices\" must be an array, got an object");
        member_ = Member::Vertices;
        out_.has_vertices = true;
      } else {
        member_ = Member::Other;
        dom_.begin(&out_.root[member_key_]);
        dom_.open(is_object ? json::object() : json::array());
      }
      return true;
    }
    if (member_ == Member::CityObjects && depth_ == 3) {
      object_ok_ = is_object;
      if (is_object) {
        object_begin_ = buf_.position() - 1;  // the '{' was just consumed
        links_ = json::object();
      } else {
        out_.problems.push_back("CityObject \"" + object_id_ + "\" is not a JSON object; skipped");
      }
    } else if (member_ == Member::Vertices) {
      if (depth_ == 3) {
        components_ = 0;
        vertex_bad_ = is_object;
      } else {
        vertex_bad_ = true;  // nested deeper than [x, y, z]
      }
    }
    return true;
  }

  bool close(bool is_object) {
    if (dom_.active()) {
      dom_.close();
      --depth_;
      return true;
    }
    if (member_ == Member::CityObjects && depth_ == 3 && is_object && object_ok_) record_object();
    if (member_ == Member::Vertices && depth_ == 3) end_vertex();
    if (depth_ == 2) member_ = Member::None;
    --depth_;
    return true;
  }

  bool vertex_component(double d) {
    if (depth_ != 3) {
      vertex_bad_ = true;
      if (depth_ == 2) end_vertex();
      return true;
    }
    if (components_ < 3) xyz_[components_] = d;
    ++components_;
    return true;
  }

  void end_vertex() {
    if (vertex_bad_ || components_ != 3) {
      vlog_.add("vertex #" + std::to_string(out_.vertex_count) +
                " is not an array of 3 numbers; faces using it are skipped");
      xyz_[0] = xyz_[1] = xyz_[2] = std::numeric_limits<double>::quiet_NaN();
    }
    spill_.append(xyz_, sizeof xyz_);
    ++out_.vertex_count;
    vertex_bad_ = false;
    components_ = 0;
  }

  void record_object() {
    ObjectEntry e;
    e.begin = object_begin_;
    e.end = buf_.position();  // just after the '}'
    e.id_offset = static_cast<uint32_t>(out_.ids.size());
    e.id_size = static_cast<uint32_t>(object_id_.size());
    out_.ids += object_id_;
    const auto index = static_cast<uint32_t>(out_.objects.size());
    out_.objects.push_back(e);
    for (const char* k : {"parents", "children"}) {
      auto it = links_.find(k);
      if (it == links_.end() || !it->is_array()) continue;
      for (auto& p : *it)
        if (p.is_string())
          (k[0] == 'p' ? out_.parent_refs : out_.child_refs).emplace_back(index, p.get<std::string>());
    }
  }

  bool stop(std::string why) {
    fatal = std::move(why);
    return false;
  }

  PositionedBuf& buf_;
  ScratchFile& spill_;
  DocumentIndex& out_;
  ProblemLog vlog_;
  DomBuilder dom_;
  int depth_ = 0;
  Member member_ = Member::None;
  std::string member_key_, object_id_;
  json links_;
  bool object_ok_ = false;
  uint64_t object_begin_ = 0;
  double xyz_[3] = {0, 0, 0};
  int components_ = 0;
  bool vertex_bad_ = false;
};

}  // namespace

DocumentIndex scan_document(int fd, const std::string& source, ScratchFile& vertex_spill) {
  DocumentIndex index;
  PositionedBuf buf(fd);
  std::istream in(&buf);
  Scanner scanner(buf, vertex_spill, index);
  bool ok = false;
  try {
    ok = json::sax_parse(in, &scanner);
  } catch (const json::exception& e) {  // e.g. invalid UTF-8 surfacing as an exception
    throw ReadError(source + ": malformed JSON: " + e.what());
  }
  if (buf.io_error()) throw ReadError(source + ": I/O error while reading");
  if (!ok) throw ReadError(source + ": " + (scanner.fatal.empty() ? "malformed JSON" : scanner.fatal));
  scanner.finish();
  vertex_spill.flush();
  return index;
}

}  // namespace mc::io
