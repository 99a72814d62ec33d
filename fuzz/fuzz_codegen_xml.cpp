// Fuzz harness for the generator's XML reader and writer (codegen/src/xml.hpp), compiled into
// the harness (the fuzz build does not configure the generator library; see fuzz_codegen.cpp).
//
// The input is the file's bytes. Properties:
// * parse() returns a document exactly when it reported no error, and it reports at most one
//   (reading stops at the first); a diagnostic names the file, a line >= 0 and a column >= 0.
// * A document read is written back by xml::writer (namespace declarations as xmlns
//   attributes, attributes, text, children) and that reads back to the same tree: names,
//   namespace URIs, attribute names and values, text.
#include "check.hpp"

#include "../codegen/src/text.cpp"
#include "../codegen/src/xml.cpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace gen = fieldcodec::gen;
namespace xml = fieldcodec::gen::xml;

namespace {

void write_tree(xml::writer &w, const xml::element &e) {
  w.open(e.name);
  for (const auto &[prefix, uri] : e.namespaces) {
    w.attribute(prefix.empty() ? std::string("xmlns") : "xmlns:" + std::string(prefix), uri);
  }
  for (const auto &a : e.attributes) w.attribute(a.name, a.value);
  w.text(e.text);
  for (const auto &c : e.children) write_tree(w, c);
  w.close();
}

bool same_tree(const xml::element &a, const xml::element &b) {
  if (a.name != b.name || a.local != b.local || a.ns != b.ns || a.text != b.text ||
      a.attributes.size() != b.attributes.size() || a.children.size() != b.children.size() ||
      a.namespaces.size() != b.namespaces.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.attributes.size(); ++i) {
    const auto &x = a.attributes[i];
    const auto &y = b.attributes[i];
    if (x.name != y.name || x.ns != y.ns || x.value != y.value) return false;
  }
  for (std::size_t i = 0; i < a.children.size(); ++i) {
    if (!same_tree(a.children[i], b.children[i])) return false;
  }
  return true;
}

void check_diagnostics(const gen::diagnostics &diag, bool parsed) {
  FUZZ_CHECK(parsed == !diag.has_errors());
  FUZZ_CHECK(diag.all().size() <= 1U);
  for (const auto &d : diag.all()) {
    FUZZ_CHECK(d.file == "fuzz.xml");
    FUZZ_CHECK(d.line >= 0 && d.column >= 0);
    FUZZ_CHECK(!d.message.empty());
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char *>(data), size);
  xml::limits lim;
  lim.max_bytes = 1U << 20U;
  gen::diagnostics diag;
  const auto doc = xml::parse(bytes, "fuzz.xml", diag, lim);
  check_diagnostics(diag, doc.has_value());
  if (!doc) return 0;
  xml::writer w;
  write_tree(w, doc->root);
  gen::diagnostics diag2;
  const auto again = xml::parse(w.str(), "fuzz.xml", diag2, lim);
  check_diagnostics(diag2, again.has_value());
  FUZZ_CHECK(again.has_value());
  FUZZ_CHECK(same_tree(doc->root, again->root));
  FUZZ_CHECK(again->encoding == "UTF-8");
  return 0;
}
