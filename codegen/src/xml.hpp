// fieldcodec-gen — a small, strict XML 1.0 reader and writer for the device descriptions the
// generator reads and writes (XDD/XDC: ISO 15745 / EPSG DS 311 / CiA 311; ESI: ETG.2000).
//
// What it reads (docs/generator.md, "The XML reader"): elements, attributes, namespaces (prefixes
// resolved to their URIs), character data, CDATA sections, comments, processing instructions and
// the XML declaration, the five predefined entity references and character references; UTF-8
// (with or without byte-order mark), UTF-16 LE/BE (byte-order mark, or "<?" as UTF-16 without
// one), ISO-8859-1, Windows-1252 and US-ASCII when the declaration names them. What it refuses,
// each with file:line:column: a document type declaration (no DTDs, no entities of a file's own),
// an encoding it does not know, bytes that are not text of the encoding, anything that is not
// well-formed (XML 1.0 section 2), undeclared prefixes, duplicate attributes, and documents
// beyond the limits (size, depth, elements, attributes). Reading stops at the first error.
#pragma once

#include "diag.hpp"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace fieldcodec::gen::xml {

/// A place in the document: 1-based line and column (columns count characters, not bytes).
struct position {
  int line = 0;
  int column = 0;
};

struct attribute {
  std::string_view name;  ///< qualified name as written ("xsi:type")
  std::string_view local; ///< the name without its prefix ("type")
  std::string_view ns;    ///< namespace URI of the prefix; empty for unprefixed attributes
  std::string value;      ///< references replaced, white space normalised (XML 1.0 3.3.3)
  position at;            ///< of the name
  position value_at;      ///< of the first character inside the quotes
};

struct element {
  std::string_view name;  ///< qualified name as written ("q1:DeviceIdentity")
  std::string_view local; ///< the name without its prefix ("DeviceIdentity")
  std::string_view ns;    ///< namespace URI (default namespace for unprefixed names), or empty
  std::vector<attribute> attributes; ///< in document order (namespace declarations excluded)
  /// The namespace declarations of the start tag (prefix, URI; "" prefix: xmlns="…").
  std::vector<std::pair<std::string_view, std::string_view>> namespaces;
  std::vector<element> children; ///< child elements in document order
  /// The character data directly inside this element (CDATA included, references replaced, line
  /// ends as LF). In an element with child elements, data that is only white space is dropped.
  std::string text;
  position at;      ///< of the '<' of the start tag
  position text_at; ///< of the first character of `text` (0:0 when there is none)

  /// The attribute of this local name (no prefix, or any prefix when `any_prefix`).
  [[nodiscard]] const attribute *find_attribute(std::string_view local_name,
                                                bool any_prefix = false) const noexcept;
  /// The first child element of this local name.
  [[nodiscard]] const element *find_child(std::string_view local_name) const noexcept;
  /// Every child element of this local name.
  [[nodiscard]] std::vector<const element *> children_named(std::string_view local_name) const;
};

/// Limits on what a document may hold (beyond them the reader refuses it).
struct limits {
  std::size_t max_bytes = std::size_t{64} << 20U; ///< size of the file as read
  std::size_t max_depth = 100;                    ///< nesting of elements
  std::size_t max_elements = 4'000'000;           ///< elements in the document
  std::size_t max_attributes = 1024;              ///< attributes of one element
};

class document {
public:
  element root;
  std::string encoding;          ///< the encoding read: UTF-8, UTF-16LE, UTF-16BE, ISO-8859-1, ...
  std::string declared_encoding; ///< as the declaration names it (empty without one)
  bool byte_order_mark = false;
  std::size_t element_count = 0;

  document();
  document(document &&) noexcept;
  document &operator=(document &&) noexcept;
  document(const document &) = delete;
  document &operator=(const document &) = delete;
  ~document();

  /// Storage the names and namespace URIs of the tree are views into (kept across moves).
  struct storage {
    std::string text;                        ///< the document as UTF-8
    std::set<std::string, std::less<>> uris; ///< namespace URIs
  };
  std::unique_ptr<storage> store;
};

/// Reads `bytes` (the file as stored); `file` names it in diagnostics. Returns nothing after an
/// error (exactly one is reported: the first).
[[nodiscard]] std::optional<document> parse(std::string_view bytes, const std::string &file,
                                            diagnostics &diag, const limits &lim = {});

/// Writes XML: UTF-8, LF line ends, two spaces of indentation, `&amp;` `&lt;` `&gt;` `&quot;`
/// and character references for TAB, LF and CR where a reader would otherwise normalise them.
/// What parse() reads back from it is the tree it was written from.
class writer {
public:
  /// Starts with the XML declaration (`<?xml version="1.0" encoding="UTF-8"?>`).
  writer();
  /// `<!-- text -->` ("--" in `text` is written as "- -").
  void comment(std::string_view text);
  /// `<name` — attributes follow, then end_start() or a child/text/close.
  void open(std::string_view name);
  void attribute(std::string_view name, std::string_view value);
  /// Character data of the element just opened (its children, if any, follow it).
  void text(std::string_view value);
  /// Closes the innermost open element (`/>` when it is empty).
  void close();
  /// `<name>text</name>` in one call.
  void leaf(std::string_view name, std::string_view value);
  /// The document so far (all elements must be closed).
  [[nodiscard]] const std::string &str() const noexcept { return out_; }

  static void append_escaped(std::string &out, std::string_view s, bool attribute);

private:
  void finish_start_tag();
  struct open_element {
    std::string name;
    bool has_children = false;
    bool has_text = false;
  };
  std::string out_;
  std::vector<open_element> stack_;
  bool in_start_tag_ = false;
};

} // namespace fieldcodec::gen::xml
