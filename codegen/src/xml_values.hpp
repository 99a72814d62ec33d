// fieldcodec-gen — values of the XML device descriptions (XDD/XDC attributes, ESI elements) into
// the model: one set of rules for both readers, on the number parsers of text.hpp.
#pragma once

#include "diag.hpp"
#include "model.hpp"
#include "xml.hpp"

#include <optional>
#include <string>
#include <string_view>

namespace fieldcodec::gen {

/// Which value of an entry a text is.
enum class value_role : std::uint8_t { default_value, actual_value, low_limit, high_limit };

/// Where a text of an XML reader is, and what it is (for its diagnostics).
struct xml_place {
  const std::string &file;
  diagnostics &diag;
  xml::position at; ///< of the first character of the text
  std::string what; ///< "defaultValue of object 0x1000 sub 0x00"
};

/// Reads `text` as the value `role` of `e`, whose data type is set: integers (decimal, `0x…`,
/// `#x…`; signed types also as their two's complement bit pattern), BOOLEAN as `true`/`false`
/// (any case) or 1/0, REAL32/REAL64 as decimals or `0x…` bit patterns, `$NODEID+…` expressions,
/// VISIBLE_STRING as it is, UNICODE_STRING as UTF-16LE, OCTET_STRING/DOMAIN as hex digit pairs.
/// A value that does not fit its type is kept with a warning; a limit of a byte string, or an
/// OCTET_STRING that is not hex digit pairs, is ignored with a warning. Returns false after an
/// error (the text is not a value of the type).
bool read_xml_value(const xml_place &place, std::string_view text, entry &e, value_role role);

/// Checks what read_xml_value() filled in: a low limit above the high limit, a default or actual
/// value outside the limits are warnings (an error under --strict). Returns false after an error.
bool check_value_range(const xml_place &place, const entry &e);

/// The label of `parent` in `language` (`<label lang="en">…</label>`, the ISO 15745 and
/// ETG.2000 form is `<Name LcId="1033">` and handled by the ESI reader), else the first
/// label. `other_languages` receives the languages of the labels not taken.
[[nodiscard]] const xml::element *pick_label(const xml::element &parent, std::string_view language,
                                             std::string_view element_name,
                                             std::string_view language_attribute,
                                             std::vector<std::string> &other_languages);

/// The XDD reader on a document read already (read_esi reads an XDD given as .xml with it).
[[nodiscard]] std::optional<dictionary>
read_xdd_document(const xml::document &doc, const std::string &file, diagnostics &diag);

} // namespace fieldcodec::gen
