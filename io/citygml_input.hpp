// A CityGML file opened for libxml2's pull parser, safe against hostile XML. zlib reads it (plain
// or gzip) and hands libxml2 the bytes through a callback that first checks the prolog: a DOCTYPE
// declaring entities is refused before libxml2 sees it ("billion laughs"). libxml2's own limits
// stay on (no XML_PARSE_HUGE): 10,000,000 bytes per text node, name or attribute value, 256 levels
// of nesting. Errors come out in plain words, the input's (gzip, refused entities) before the
// parser's.
#pragma once
#include <libxml/parser.h>
#include <libxml/xmlreader.h>
#include <zlib.h>

#include <string>

namespace mc::io::citygml {

// Scans the bytes before the root element for "<!ENTITY" (legal only inside a DOCTYPE's internal
// subset). It knows comments, processing instructions and quoted literals, so text inside them
// neither hides nor fakes a declaration; UTF-16 input is read by its code units.
class PrologGuard {
 public:
  // False from the first entity declaration on. Cheap once done().
  bool feed(const unsigned char* p, size_t n);
  bool done() const { return state_ == State::Done; }
  int line() const { return line_; }

 private:
  enum class State { Text, Lt, Pi, PiEnd, Bang, Comment, Decl, Done, Refused };
  void step(unsigned c);

  State state_ = State::Text;
  int unit_ = 0;  // 0 not known yet, 1 bytes (UTF-8, ISO-8859-x), 2 UTF-16LE, 3 UTF-16BE
  unsigned char held_[2] = {0, 0};
  int nheld_ = 0;
  bool subset_ = false, doctype_ = false;
  unsigned quote_ = 0;
  int dashes_ = 0, line_ = 1;
  std::string word_;  // after "<!": "--", "DOCTYPE", "ENTITY", ...
};

class XmlInput {
 public:
  // A pull reader over the file: reader(). Throws ReadError when the file cannot be opened.
  explicit XmlInput(const std::string& path);
  // A SAX parser over the file, for a pass that builds nothing (several times faster than the
  // pull reader): parse() calls `callbacks` with `user` as their context. Same input, same checks,
  // same limits as the pull reader's.
  XmlInput(const std::string& path, xmlSAXHandler callbacks, void* user);
  ~XmlInput();
  XmlInput(const XmlInput&) = delete;
  XmlInput& operator=(const XmlInput&) = delete;

  xmlTextReaderPtr reader() const { return reader_; }
  // SAX: parses the whole file; false when it stopped early (an input or XML error, or stop()).
  bool parse();
  // SAX, from a callback: ends the parse.
  void stop();
  // Why reading stopped: "truncated gzip file: ...", "entity declarations are not accepted ...",
  // or "malformed XML: line N: ..." (libxml2's message, its limits explained); never empty.
  std::string failure() const;

 private:
  void open();
  static int read(void* self, char* buffer, int len);
  static void on_error(void* self, xmlErrorPtr e);
  void note(const xmlError& e);

  std::string path_, input_error_, xml_error_;
  gzFile gz_ = nullptr;
  PrologGuard guard_;
  xmlTextReaderPtr reader_ = nullptr;
  xmlParserCtxtPtr sax_ = nullptr;
  bool stopped_ = false;
};

}  // namespace mc::io::citygml
