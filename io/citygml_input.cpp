#include "io/citygml_input.hpp"

#include <cerrno>
#include <cstring>

#include "io/errors.hpp"

namespace mc::io::citygml {

namespace {

// libxml2's messages for its limits, said in plain words (the original kept in parentheses).
std::string explain(const std::string& msg) {
  static const struct {
    const char* needle;
    const char* meaning;
  } known[] = {
      {"huge text node", "a text node is longer than 10,000,000 bytes, libxml2's limit"},
      {"text too long", "a text node is longer than 10,000,000 bytes, libxml2's limit"},
      {"Excessive depth", "elements are nested deeper than 256 levels, libxml2's limit"},
      {"too deep", "declarations are nested deeper than libxml2's limit"},
      {"Huge input lookup",
       "a name, attribute value, comment or other markup is longer than 10,000,000 bytes, libxml2's limit"},
      {"too long", "a name or attribute value is longer than libxml2's limit"},
      {"too big", "a comment, CDATA section or processing instruction is longer than libxml2's limit"},
      {"entity reference loop",
       "entity references expand too much (entity declarations are not accepted in CityGML)"},
  };
  for (const auto& k : known)
    if (msg.find(k.needle) != std::string::npos) return std::string(k.meaning) + " (" + msg + ")";
  return msg;
}

}  // namespace

bool PrologGuard::feed(const unsigned char* p, size_t n) {
  for (size_t i = 0; i < n && state_ != State::Done && state_ != State::Refused; ++i) {
    if (unit_ == 0) {  // the first two bytes tell UTF-16 (a byte order mark or "<" and a zero)
      held_[nheld_++] = p[i];
      if (nheld_ < 2) continue;
      const unsigned a = held_[0], b = held_[1];
      unit_ = (a == 0xFF && b == 0xFE) || (a == '<' && b == 0)   ? 2
              : (a == 0xFE && b == 0xFF) || (a == 0 && b == '<') ? 3
                                                                 : 1;
      nheld_ = 0;
      if (unit_ == 1) {
        step(a);
        step(b);
      } else {
        step(unit_ == 2 ? a | b << 8 : a << 8 | b);
      }
      continue;
    }
    if (unit_ == 1) {
      step(p[i]);
      continue;
    }
    held_[nheld_++] = p[i];
    if (nheld_ == 2) {
      step(unit_ == 2 ? held_[0] | held_[1] << 8 : held_[0] << 8 | held_[1]);
      nheld_ = 0;
    }
  }
  return state_ != State::Refused;
}

void PrologGuard::step(unsigned c) {
  if (c == '\n') ++line_;
  switch (state_) {
    case State::Text:
      if (c == '<') state_ = State::Lt;
      else if (c == ']') subset_ = false;  // the internal subset ends; "]>" closes the DOCTYPE
      break;
    case State::Lt:
      if (c == '?') {
        state_ = State::Pi;
      } else if (c == '!') {
        state_ = State::Bang;
        word_.clear();
      } else {
        state_ = State::Done;  // the root element (or not XML: libxml2 says so)
      }
      break;
    case State::Pi:
      if (c == '?') state_ = State::PiEnd;
      break;
    case State::PiEnd:
      state_ = c == '>' ? State::Text : c == '?' ? State::PiEnd : State::Pi;
      break;
    case State::Bang:
      word_.push_back(static_cast<char>(c < 0x80 ? c : '?'));
      if (word_ == "--") {
        state_ = State::Comment;
        dashes_ = 0;
      } else if (word_ == "ENTITY") {
        state_ = State::Refused;
      } else if (word_ == "DOCTYPE" ||
                 ((word_ == "ELEMENT" || word_ == "ATTLIST" || word_ == "NOTATION") && subset_)) {
        doctype_ = word_ == "DOCTYPE";
        quote_ = 0;
        state_ = State::Decl;
      } else if (word_.size() >= 8) {
        state_ = State::Done;  // not a declaration this guard knows: libxml2 reports it
      }
      break;
    case State::Comment:
      if (c == '>' && dashes_ >= 2) state_ = State::Text;
      dashes_ = c == '-' ? dashes_ + 1 : 0;
      break;
    case State::Decl:
      if (quote_) {
        if (c == quote_) quote_ = 0;
      } else if (c == '"' || c == '\'') {
        quote_ = c;
      } else if (c == '[' && doctype_) {
        subset_ = true;
        state_ = State::Text;
      } else if (c == '>') {
        state_ = State::Text;
      }
      break;
    case State::Done:
    case State::Refused:
      break;
  }
}

// NONET: never fetch schemas or DTDs; COMPACT: smaller text nodes. No XML_PARSE_HUGE: libxml2's
// limits bound what one node can cost.
constexpr int kOptions = XML_PARSE_NONET | XML_PARSE_COMPACT;

void XmlInput::open() {
  gz_ = gzopen(path_.c_str(), "rb");  // plain files are read as they are ("transparent" mode)
  if (!gz_) throw ReadError(path_ + ": cannot open: " + std::strerror(errno ? errno : ENOMEM));
  gzbuffer(gz_, 1 << 17);
}

XmlInput::XmlInput(const std::string& path) : path_(path) {
  open();
  reader_ = xmlReaderForIO(&XmlInput::read, nullptr, this, path.c_str(), nullptr, kOptions);
  if (!reader_) {
    gzclose(gz_);
    throw ReadError(path + ": cannot open as XML" + (input_error_.empty() ? "" : ": " + input_error_));
  }
  xmlTextReaderSetStructuredErrorHandler(reader_, &XmlInput::on_error, this);
}

XmlInput::XmlInput(const std::string& path, xmlSAXHandler callbacks, void* user) : path_(path) {
  open();
  callbacks.initialized = XML_SAX2_MAGIC;
  // Quiet: the parser keeps its first error in the context (parse() takes it from there); the
  // callbacks' context is `user`, not this.
  callbacks.serror = [](void*, xmlErrorPtr) {};
  sax_ = xmlCreateIOParserCtxt(&callbacks, user, &XmlInput::read, nullptr, this, XML_CHAR_ENCODING_NONE);
  if (!sax_) {
    gzclose(gz_);
    throw ReadError(path + ": cannot open as XML" + (input_error_.empty() ? "" : ": " + input_error_));
  }
  xmlCtxtUseOptions(sax_, kOptions);
}

XmlInput::~XmlInput() {
  if (reader_) xmlFreeTextReader(reader_);
  if (sax_) xmlFreeParserCtxt(sax_);
  gzclose(gz_);
}

bool XmlInput::parse() {
  const int rc = xmlParseDocument(sax_);
  if (sax_->lastError.code != XML_ERR_OK) note(sax_->lastError);
  return rc == 0 && sax_->wellFormed && !stopped_ && input_error_.empty();
}

void XmlInput::stop() {
  stopped_ = true;
  xmlStopParser(sax_);
}

std::string XmlInput::failure() const {
  if (!input_error_.empty()) return input_error_;
  return "malformed XML: " + (xml_error_.empty() ? std::string("unknown error") : xml_error_);
}

int XmlInput::read(void* self, char* buffer, int len) {
  auto* in = static_cast<XmlInput*>(self);
  if (!in->input_error_.empty()) return -1;
  const int n = gzread(in->gz_, buffer, static_cast<unsigned>(len));
  if (n <= 0) {
    // zlib decodes ahead into its buffer and flags a truncated or corrupt stream early, while the
    // bytes before the damage still wait to be read: the error counts once nothing is left.
    int code = Z_OK;
    const char* msg = gzerror(in->gz_, &code);
    if (n == 0 && code == Z_OK) return 0;
    std::string zlib = msg && *msg ? msg : "unknown error";
    if (zlib.rfind(in->path_ + ": ", 0) == 0)
      zlib.erase(0, in->path_.size() + 2);  // the path is said already
    if (code == Z_BUF_ERROR)
      in->input_error_ = "truncated gzip file: it ends before its gzip trailer (zlib: " + zlib + ")";
    else if (code == Z_DATA_ERROR) in->input_error_ = "corrupt gzip data (zlib: " + zlib + ")";
    else if (code == Z_ERRNO) in->input_error_ = std::string("read error: ") + std::strerror(errno);
    else in->input_error_ = "gzip error (zlib: " + zlib + ")";
    return -1;
  }
  if (!in->guard_.done() &&
      !in->guard_.feed(reinterpret_cast<const unsigned char*>(buffer), static_cast<size_t>(n))) {
    in->input_error_ = "entity declarations are not accepted in CityGML (<!ENTITY in the DOCTYPE, line " +
                       std::to_string(in->guard_.line()) +
                       "): entities can expand a few bytes into gigabytes (\"billion laughs\")";
    return -1;
  }
  return n;
}

void XmlInput::on_error(void* self, xmlErrorPtr e) {
  if (e) static_cast<XmlInput*>(self)->note(*e);
}

void XmlInput::note(const xmlError& e) {
  if (!xml_error_.empty() || e.level < XML_ERR_ERROR) return;
  std::string msg = e.message ? e.message : "XML error";
  while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
  xml_error_ = "line " + std::to_string(e.line) + ": " + explain(msg);
}

}  // namespace mc::io::citygml
