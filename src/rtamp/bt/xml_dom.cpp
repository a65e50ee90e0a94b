#include "rtamp/bt/xml_dom.hpp"

#include <expat.h>

#include <cctype>
#include <climits>
#include <exception>
#include <memory>

namespace rtamp::bt {

const std::string* XmlElement::attribute(std::string_view name) const {
  for (const auto& [k, v] : attributes) {
    if (k == name) return &v;
  }
  return nullptr;
}

namespace {

struct Builder {
  XML_Parser parser = nullptr;
  XmlDocument doc;
  std::vector<XmlElement*> stack;  // open elements; stack[0] is doc.root
  bool have_root = false;
  std::string file;
  std::exception_ptr failure;  // an exception thrown inside a callback (rethrown after parsing)

  void fail(const std::string& what) {
    if (!failure) {
      failure = std::make_exception_ptr(
          rtamp::Error(what, SourceLocation{file, static_cast<int>(XML_GetCurrentLineNumber(parser)),
                                            static_cast<int>(XML_GetCurrentColumnNumber(parser)) + 1}));
    }
    XML_StopParser(parser, XML_FALSE);
  }
};

void XMLCALL on_start(void* data, const XML_Char* name, const XML_Char** attrs) {
  auto& b = *static_cast<Builder*>(data);
  try {
    if (static_cast<int>(b.stack.size()) >= kMaxXmlDepth) {
      b.fail("XML elements nested deeper than " + std::to_string(kMaxXmlDepth) + " levels");
      return;
    }
    XmlElement* e = nullptr;
    if (b.stack.empty()) {
      e = &b.doc.root;
      b.have_root = true;
    } else {
      e = &b.stack.back()->children.emplace_back();
    }
    e->tag = name;
    e->line = static_cast<int>(XML_GetCurrentLineNumber(b.parser));
    e->column = static_cast<int>(XML_GetCurrentColumnNumber(b.parser)) + 1;
    for (int i = 0; attrs[i] != nullptr; i += 2) e->attributes.emplace_back(attrs[i], attrs[i + 1]);
    b.stack.push_back(e);
  } catch (...) {
    b.failure = std::current_exception();
    XML_StopParser(b.parser, XML_FALSE);
  }
}

void XMLCALL on_end(void* data, const XML_Char*) {
  auto& b = *static_cast<Builder*>(data);
  if (!b.stack.empty()) b.stack.pop_back();
}

void XMLCALL on_text(void* data, const XML_Char* s, int len) {
  auto& b = *static_cast<Builder*>(data);
  if (b.stack.empty()) return;
  try {
    b.stack.back()->text.append(s, static_cast<std::size_t>(len));
  } catch (...) {
    b.failure = std::current_exception();
    XML_StopParser(b.parser, XML_FALSE);
  }
}

void XMLCALL on_comment(void* data, const XML_Char* s) {
  auto& b = *static_cast<Builder*>(data);
  if (b.have_root) return;
  try {
    b.doc.leading_comments.emplace_back(s);
  } catch (...) {
    b.failure = std::current_exception();
    XML_StopParser(b.parser, XML_FALSE);
  }
}

// The XML declaration: the parser reads UTF-8 whatever a file declares, so a
// declaration of another encoding (UTF-16 over UTF-8 bytes, Latin-1) is refused
// rather than silently misread. US-ASCII is a subset of UTF-8.
void XMLCALL on_declaration(void* data, const XML_Char* /*version*/, const XML_Char* encoding, int /*standalone*/) {
  auto& b = *static_cast<Builder*>(data);
  if (encoding == nullptr) return;
  std::string e(encoding);
  for (char& c : e) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (e != "UTF-8" && e != "UTF8" && e != "US-ASCII" && e != "ASCII")
    b.fail(std::string("the XML declaration names encoding \"") + encoding +
           "\": rtamp reads behavior-tree files as UTF-8 (convert the file, e.g. with iconv, and declare UTF-8)");
}

}  // namespace

XmlDocument parse_xml(std::string_view text, const std::string& file) {
  if (text.size() > static_cast<std::size_t>(INT_MAX)) throw rtamp::Error("XML text too large", {file});
  std::unique_ptr<std::remove_pointer_t<XML_Parser>, void (*)(XML_Parser)> parser(XML_ParserCreate("UTF-8"),
                                                                                   XML_ParserFree);
  if (!parser) throw rtamp::Error("cannot create an XML parser (out of memory)", {file});
  Builder b;
  b.parser = parser.get();
  b.file = file;
  XML_SetUserData(b.parser, &b);
  XML_SetElementHandler(b.parser, on_start, on_end);
  XML_SetCharacterDataHandler(b.parser, on_text);
  XML_SetCommentHandler(b.parser, on_comment);
  XML_SetXmlDeclHandler(b.parser, on_declaration);
  const XML_Status st = XML_Parse(b.parser, text.data(), static_cast<int>(text.size()), XML_TRUE);
  if (b.failure) std::rethrow_exception(b.failure);
  if (st != XML_STATUS_OK) {
    throw rtamp::Error(std::string("malformed XML: ") + XML_ErrorString(XML_GetErrorCode(b.parser)),
                       SourceLocation{file, static_cast<int>(XML_GetCurrentLineNumber(b.parser)),
                                      static_cast<int>(XML_GetCurrentColumnNumber(b.parser)) + 1});
  }
  if (!b.have_root) throw rtamp::Error("malformed XML: no root element", SourceLocation{file, 1, 1});
  return std::move(b.doc);
}

}  // namespace rtamp::bt
