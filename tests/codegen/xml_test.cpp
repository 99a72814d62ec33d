// fieldcodec-gen's XML reader and writer (codegen/src/xml.hpp): what it reads, every refusal
// with its exact place, the encodings, the limits, and the writer's round trip.
#include "xml.hpp"

#include <doctest/doctest.h>

#include <string>
#include <vector>

namespace gen = fieldcodec::gen;
namespace xml = fieldcodec::gen::xml;

namespace {

struct parsed {
  std::optional<xml::document> doc;
  std::string diag; ///< the one diagnostic (empty when none)
};

parsed parse(std::string_view text, const xml::limits &lim = {}) {
  gen::diagnostics d;
  parsed p;
  p.doc = xml::parse(text, "t.xml", d, lim);
  CHECK(p.doc.has_value() == !d.has_errors());
  CHECK(d.all().size() <= 1U);
  if (!d.all().empty()) p.diag = gen::diagnostics::format(d.all().front());
  return p;
}

std::string error_of(std::string_view text, const xml::limits &lim = {}) {
  const parsed p = parse(text, lim);
  CHECK(!p.doc);
  return p.diag;
}

// UTF-16 bytes of ASCII/BMP text (little or big endian), with or without a byte-order mark.
std::string utf16(std::u16string_view s, bool little, bool bom) {
  std::string out;
  auto put = [&](char16_t u) {
    const auto lo = static_cast<char>(u & 0xFFU);
    const auto hi = static_cast<char>((u >> 8U) & 0xFFU);
    out += little ? lo : hi;
    out += little ? hi : lo;
  };
  if (bom) put(0xFEFF);
  for (const char16_t u : s) put(u);
  return out;
}

} // namespace

TEST_CASE("xml: elements, attributes, text, positions") {
  const parsed p = parse("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
                         "<!-- a comment -->\n"
                         "<a x=\"1\" y='two &amp; &lt;three&gt;'>\n"
                         "  <b>text &#65;&#x42; <![CDATA[<raw & ]]>]] end</b>\n"
                         "  <c/><?pi some data?>\n"
                         "  <d k=\"a\tb\r\nc\"> </d>\n"
                         "</a>\n");
  INFO(p.diag);
  REQUIRE(p.doc);
  const xml::element &a = p.doc->root;
  CHECK(a.name == "a");
  CHECK(a.at.line == 3);
  CHECK(a.at.column == 1);
  REQUIRE(a.attributes.size() == 2);
  CHECK(a.attributes[1].value == "two & <three>");
  CHECK(a.attributes[1].at.line == 3);
  CHECK(a.attributes[1].at.column == 10);
  CHECK(a.attributes[1].value_at.column == 13);
  CHECK(a.text.empty()); // white space beside child elements is dropped
  REQUIRE(a.children.size() == 3);
  const xml::element &b = a.children[0];
  CHECK(b.text == "text AB <raw & ]] end");
  CHECK(b.text_at.line == 4);
  CHECK(b.text_at.column == 6);
  CHECK(a.children[1].name == "c");
  CHECK(a.children[1].children.empty());
  CHECK(a.children[2].find_attribute("k")->value == "a b c"); // TAB, CR LF normalised
  CHECK(a.children[2].text == " ");                           // no child elements: kept
  CHECK(a.find_child("d") == &a.children[2]);
  CHECK(a.find_child("e") == nullptr);
  CHECK(p.doc->encoding == "UTF-8");
  CHECK(p.doc->declared_encoding == "UTF-8");
  CHECK(p.doc->element_count == 4U);
}

TEST_CASE("xml: namespaces are resolved from their prefixes") {
  const parsed p =
      parse("<c xmlns=\"urn:default\" xmlns:xsi=\"http://www.w3.org/2001/XMLSchema-instance\">"
            "<b xmlns:q1=\"urn:q\" xsi:type=\"q1:T\"><q1:x/><y xmlns=\"\"/></b><q1:z "
            "xmlns:q1=\"urn:r\"/></c>");
  REQUIRE(p.doc);
  const xml::element &c = p.doc->root;
  CHECK(c.ns == "urn:default");
  const xml::element &b = c.children[0];
  CHECK(b.ns == "urn:default");
  REQUIRE(b.attributes.size() == 1); // namespace declarations are not attributes
  CHECK(b.attributes[0].local == "type");
  CHECK(b.attributes[0].ns == "http://www.w3.org/2001/XMLSchema-instance");
  CHECK(b.find_attribute("type") == nullptr); // prefixed: only with any_prefix
  CHECK(b.find_attribute("type", true)->value == "q1:T");
  CHECK(b.children[0].local == "x");
  CHECK(b.children[0].ns == "urn:q");
  CHECK(b.children[1].ns.empty()); // xmlns="" undeclares the default namespace
  CHECK(c.children[1].ns == "urn:r");
  CHECK(error_of("<a><q1:x/></a>") ==
        "t.xml:1:4: error: undeclared namespace prefix 'q1' in '<q1:x>'");
  CHECK(error_of("<a xmlns:q=\"u\"><b/></a><!-- --><q:c/>") ==
        "t.xml:1:32: error: a second root element (a document has one)");
  CHECK(error_of("<a p:x=\"1\"/>") ==
        "t.xml:1:4: error: undeclared namespace prefix 'p' in attribute 'p:x'");
  CHECK(error_of("<a xmlns:p=\"u\" xmlns:q=\"u\" p:x=\"1\" q:x=\"2\"/>") ==
        "t.xml:1:36: error: attribute 'q:x' is the same as 'p:x' (namespace u)");
  CHECK(error_of("<a xmlns:p=\"\"/>") == "t.xml:1:13: error: namespace prefix 'p' bound to an "
                                         "empty URI (XML namespaces 1.0 forbids it)");
  CHECK(error_of("<a xmlns:p=\"u\" xmlns:p=\"v\"/>") ==
        "t.xml:1:16: error: namespace declaration 'xmlns:p' appears twice in '<a>'");
}

TEST_CASE("xml: encodings") {
  const std::string body = "<a n=\"\xC3\xA4\">\xE2\x82\xAC</a>";
  SUBCASE("UTF-8 with a byte-order mark") {
    const parsed p = parse("\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"utf-8\"?>" + body);
    REQUIRE(p.doc);
    CHECK(p.doc->byte_order_mark);
    CHECK(p.doc->root.text == "\xE2\x82\xAC");
  }
  SUBCASE("ISO-8859-1 and its spellings") {
    for (const char *name : {"ISO-8859-1", "ISO8859-1", "iso_8859-1", "latin1"}) {
      CAPTURE(name);
      const parsed p = parse(std::string("<?xml version=\"1.0\" encoding=\"") + name +
                             "\"?><a n=\"\xE4\">\xB5</a>");
      REQUIRE(p.doc);
      CHECK(p.doc->encoding == "ISO-8859-1");
      CHECK(p.doc->root.find_attribute("n")->value == "\xC3\xA4");
      CHECK(p.doc->root.text == "\xC2\xB5");
    }
  }
  SUBCASE("Windows-1252") {
    const parsed p = parse("<?xml version=\"1.0\" encoding=\"windows-1252\"?><a>\x80</a>");
    REQUIRE(p.doc);
    CHECK(p.doc->root.text == "\xE2\x82\xAC");
  }
  SUBCASE("UTF-16 LE and BE, with and without byte-order mark") {
    const std::u16string s =
        u"<?xml version=\"1.0\" encoding=\"UTF-16\"?>\n<a n=\"\u00E4\">\u20AC\U0001F600</a>";
    for (const bool little : {true, false}) {
      for (const bool bom : {true, false}) {
        CAPTURE(little);
        CAPTURE(bom);
        const parsed p = parse(utf16(s, little, bom));
        REQUIRE(p.doc);
        CHECK(p.doc->encoding == (little ? "UTF-16LE" : "UTF-16BE"));
        CHECK(p.doc->root.find_attribute("n")->value == "\xC3\xA4");
        CHECK(p.doc->root.text == "\xE2\x82\xAC\xF0\x9F\x98\x80");
        CHECK(p.doc->root.at.line == 2);
      }
    }
  }
  SUBCASE("refused") {
    CHECK(error_of("<a>\xE4</a>") == "t.xml:1:4: error: byte 0xE4 is not UTF-8 (the declaration "
                                     "names no encoding, so the file must be UTF-8)");
    CHECK(error_of("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<a>x\xC3</a>") ==
          "t.xml:2:5: error: byte 0xC3 is not UTF-8 (the declaration names encoding 'UTF-8')");
    CHECK(error_of("<?xml version=\"1.0\" encoding=\"Shift_JIS\"?><a/>") ==
          "t.xml:1:31: error: encoding 'Shift_JIS' is not supported (UTF-8, UTF-16, "
          "ISO-8859-1, Windows-1252 and US-ASCII are)");
    CHECK(error_of("<?xml version=\"1.0\" encoding=\"us-ascii\"?><a>\xC3\xA4</a>") ==
          "t.xml:1:45: error: byte 0xC3 is not US-ASCII (the declaration names encoding "
          "'us-ascii')");
    CHECK(error_of("\xEF\xBB\xBF<?xml version=\"1.0\" encoding=\"ISO-8859-1\"?><a/>") ==
          "t.xml:1:31: error: the declaration names encoding 'ISO-8859-1' but the file starts "
          "with a UTF-8 byte-order mark");
    CHECK(error_of("<?xml version=\"1.0\" encoding=\"UTF-16\"?><a/>") ==
          "t.xml:1:31: error: the declaration names encoding 'UTF-16' but the file is not UTF-16 "
          "(no byte-order mark)");
    CHECK(error_of(utf16(u"<?xml version=\"1.0\" encoding=\"UTF-8\"?><a/>", true, true)) ==
          "t.xml:1:31: error: the declaration names encoding 'UTF-8' but the file is UTF-16LE");
    CHECK(error_of(utf16(u"<a>\xD800x</a>", true, true)) ==
          "t.xml:1:4: error: unpaired UTF-16 surrogate 0xD800");
    CHECK(error_of(utf16(u"<a/>", false, true) + "x") ==
          "t.xml:1:5: error: odd number of bytes in a UTF-16 file (the last character is cut)");
    CHECK(error_of(std::string("\xFF\xFE\0\0", 4)) ==
          "t.xml:1:1: error: UTF-32 (byte-order mark) is not supported; use UTF-8 or UTF-16");
    CHECK(error_of(std::string("<a>\0</a>", 8)) ==
          "t.xml:1:4: error: character U+0000 is not allowed in XML (binary data, or UTF-16 "
          "without a byte-order mark?)");
    CHECK(error_of("<a>\x01</a>") == "t.xml:1:4: error: character U+0001 is not allowed in XML");
    CHECK(error_of("<a>\xEF\xBF\xBF</a>") ==
          "t.xml:1:4: error: character U+FFFF is not allowed in XML");
  }
}

TEST_CASE("xml: well-formedness errors name the place") {
  CHECK(error_of("") == "t.xml:1:1: error: expected the root element, got the end of the file");
  CHECK(error_of("  \n  ") ==
        "t.xml:2:3: error: expected the root element, got the end of the file");
  CHECK(error_of("hello") == "t.xml:1:1: error: expected '<' to start the root element, got 'h'");
  CHECK(error_of("<a>\n<b>\n</a>") ==
        "t.xml:3:1: error: end tag '</a>' does not match '<b>' (line 2, column 1)");
  CHECK(error_of("<a>\n  <b>") ==
        "t.xml:2:3: error: element '<b>' is not closed (the file ends before '</b>')");
  CHECK(error_of("<a x=\"1\" x=\"2\"/>") ==
        "t.xml:1:10: error: attribute 'x' appears twice in '<a>' (first at line 1, column 4)");
  CHECK(error_of("<a x=\"1\"y=\"2\"/>") ==
        "t.xml:1:9: error: expected white space, '>' or '/>' in the start tag '<a', got 'y'");
  CHECK(error_of("<a x=1/>") ==
        "t.xml:1:6: error: expected a quoted value for attribute 'x', got '1'");
  CHECK(error_of("<a x/>") == "t.xml:1:5: error: expected '=' after attribute 'x', got '/'");
  CHECK(error_of("<a x=\"<\"/>") ==
        "t.xml:1:7: error: '<' in the value of attribute 'x' (write it as '&lt;')");
  CHECK(error_of("<a x=\"1/>") ==
        "t.xml:1:7: error: value of attribute 'x' without its closing quote");
  CHECK(error_of("<a>&nbsp;</a>") ==
        "t.xml:1:4: error: unknown entity '&nbsp;' (only &lt; &gt; &amp; &apos; &quot; and "
        "character references; the reader reads no DTD)");
  CHECK(error_of("<a>a & b</a>") == "t.xml:1:6: error: '&' must start a reference such as "
                                    "'&amp;' (write a literal '&' as '&amp;')");
  CHECK(error_of("<a>&#0;</a>") ==
        "t.xml:1:4: error: character reference '&#0;' is not an XML character");
  CHECK(error_of("<a>&#x110000;</a>") ==
        "t.xml:1:4: error: character reference '&#x110000;' is not an XML character");
  CHECK(error_of("<a>&#12a;</a>") ==
        "t.xml:1:8: error: expected a digit or ';' in a character reference, got 'a'");
  CHECK(error_of("<a>]]></a>") ==
        "t.xml:1:4: error: ']]>' in character data (write '>' as '&gt;')");
  CHECK(error_of("<a><!-- x -- y --></a>") ==
        "t.xml:1:11: error: '--' inside a comment (XML allows it only in the closing '-->')");
  CHECK(error_of("<a><!-- x </a>") == "t.xml:1:4: error: comment without '-->'");
  CHECK(error_of("<a><![CDATA[x</a>") == "t.xml:1:4: error: CDATA section without ']]>'");
  CHECK(error_of("<!DOCTYPE a [<!ENTITY e \"x\">]><a>&e;</a>") ==
        "t.xml:1:1: error: document type declarations (<!DOCTYPE …>) are not supported: the "
        "reader reads no DTD");
  CHECK(error_of("<a/>\n<?xml version=\"1.0\"?>") ==
        "t.xml:2:1: error: an XML declaration is allowed only at the very start of the file");
  CHECK(error_of("<a/>text") == "t.xml:1:5: error: text after the root element, got 't'");
  CHECK(error_of("<?xml encoding=\"UTF-8\"?><a/>") ==
        "t.xml:1:7: error: the XML declaration must start with version");
  CHECK(error_of("<?xml version=\"2.0\"?><a/>") ==
        "t.xml:1:16: error: XML version '2.0' is not supported (1.x is)");
  CHECK(error_of("<?xml version=\"1.0\" standalone=\"maybe\"?><a/>") ==
        "t.xml:1:33: error: expected standalone 'yes' or 'no', got 'maybe'");
  CHECK(error_of("<a><1/></a>") == "t.xml:1:5: error: expected an element name, got '1'");
  CHECK(error_of("<a></ a>") == "t.xml:1:6: error: expected an element name in the end tag, "
                                "got ' '");
  CHECK(error_of("<a>\n\t<!x></a>") ==
        "t.xml:2:2: error: expected '<!--' or '<![CDATA[' after '<!'");
}

TEST_CASE("xml: columns count characters, line ends are LF, CR LF and CR") {
  const parsed p = parse("<a>\r\n<b/>\r<c/>\n\xC3\xA4\xC3\xA4<d/></a>");
  REQUIRE(p.doc);
  CHECK(p.doc->root.children[0].at.line == 2);
  CHECK(p.doc->root.children[1].at.line == 3);
  CHECK(p.doc->root.children[2].at.line == 4);
  CHECK(p.doc->root.children[2].at.column == 3);       // two characters of two bytes each before it
  CHECK(p.doc->root.text == "\n\n\n\xC3\xA4\xC3\xA4"); // kept: not only white space
}

TEST_CASE("xml: limits") {
  xml::limits lim;
  lim.max_depth = 3;
  CHECK(parse("<a><b><c/></b></a>", lim).doc);
  CHECK(error_of("<a><b><c><d/></c></b></a>", lim) ==
        "t.xml:1:10: error: elements nested deeper than 3 levels (the limit of the XML reader)");
  lim = {};
  lim.max_elements = 2;
  CHECK(error_of("<a><b/><c/></a>", lim) ==
        "t.xml:1:8: error: more than 2 elements (the limit of the XML reader)");
  lim = {};
  lim.max_attributes = 1;
  CHECK(error_of("<a x=\"1\" y=\"2\"/>", lim) ==
        "t.xml:1:10: error: more than 1 attributes in one element (the limit of the XML reader)");
  lim = {};
  lim.max_bytes = 4;
  CHECK(error_of("<a/> ", lim) ==
        "t.xml: error: file of 5 bytes is larger than the limit of 4 bytes of the XML reader");
  // the default depth keeps a deeply nested file from exhausting anything
  std::string deep;
  for (int i = 0; i < 200; ++i) deep += "<a>";
  CHECK(error_of(deep) == "t.xml:1:301: error: elements nested deeper than 100 levels (the "
                          "limit of the XML reader)");
}

namespace {
bool same_tree(const xml::element &a, const xml::element &b) {
  if (a.name != b.name || a.ns != b.ns || a.text != b.text ||
      a.attributes.size() != b.attributes.size() || a.children.size() != b.children.size()) {
    return false;
  }
  for (std::size_t i = 0; i < a.attributes.size(); ++i) {
    if (a.attributes[i].name != b.attributes[i].name ||
        a.attributes[i].value != b.attributes[i].value) {
      return false;
    }
  }
  for (std::size_t i = 0; i < a.children.size(); ++i) {
    if (!same_tree(a.children[i], b.children[i])) return false;
  }
  return true;
}
} // namespace

TEST_CASE("xml: the writer writes what the reader reads back") {
  xml::writer w;
  w.comment("generated -- by a test");
  w.open("root");
  w.attribute("a", "tab\there \"quoted\" <&> line\nend\r");
  w.open("child");
  w.text("text with <markup> & ]]> and\r\nline ends");
  w.close();
  w.leaf("leaf", "x");
  w.open("empty");
  w.close();
  w.open("mixed");
  w.text("before ");
  w.leaf("inner", "i");
  w.close();
  w.close();
  const std::string text = w.str();
  CHECK(text.starts_with(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- generated - - by a test -->\n<root"));
  const parsed p = parse(text);
  REQUIRE(p.doc);
  const xml::element &r = p.doc->root;
  CHECK(r.find_attribute("a")->value == "tab\there \"quoted\" <&> line\nend\r");
  CHECK(r.children[0].text == "text with <markup> & ]]> and\r\nline ends");
  CHECK(r.children[2].children.empty());
  CHECK(r.children[3].text == "before ");
  CHECK(r.children[3].children[0].text == "i");
  // written again from the tree: the same document
  xml::writer w2;
  w2.comment("generated -- by a test");
  w2.open("root");
  w2.attribute("a", r.find_attribute("a")->value);
  w2.leaf("child", r.children[0].text);
  w2.leaf("leaf", "x");
  w2.open("empty");
  w2.close();
  w2.open("mixed");
  w2.text(r.children[3].text);
  w2.leaf("inner", "i");
  w2.close();
  w2.close();
  CHECK(w2.str() == text);
  const parsed p2 = parse(w2.str());
  REQUIRE(p2.doc);
  CHECK(same_tree(p.doc->root, p2.doc->root));
}
