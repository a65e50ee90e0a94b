// rtamp::bt::XmlElement / parse_xml — a small element tree read with expat, for
// the BehaviorTree.CPP XML importer and schema writer.
//
// Keeps what a behavior-tree file needs: element names, attributes in document
// order, character data, and the 1-based line and column of every start tag;
// comments before the root element are kept too (rtamp's export marks its files
// with one). Namespaces are not processed (attribute names such as
// xmlns:xsi stay as written). Parse errors throw rtamp::Error with the file,
// line and column expat reports; elements nested deeper than kMaxXmlDepth are an
// error (so recursive walks over the result cannot exhaust the stack).
// Invariant: every element has line >= 1 and column >= 1.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

inline constexpr int kMaxXmlDepth = 256;

struct XmlElement {
  std::string tag;
  std::vector<std::pair<std::string, std::string>> attributes;  // document order
  std::vector<XmlElement> children;
  std::string text;  // character data directly inside the element, concatenated
  int line = 0;
  int column = 0;

  // The value of an attribute, or nullptr.
  const std::string* attribute(std::string_view name) const;
};

struct XmlDocument {
  XmlElement root;
  std::vector<std::string> leading_comments;  // comments before the root element
};

// Parses `text`; `file` only labels error locations (may be empty).
XmlDocument parse_xml(std::string_view text, const std::string& file = {});

// The location of an element in `file`.
inline SourceLocation location_of(const XmlElement& e, const std::string& file) {
  return SourceLocation{file, e.line, e.column};
}

}  // namespace rtamp::bt
