#include <cstdlib>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <kit_catch.hpp>

#include <kit/app/figure.hpp>
#include <kit/app/pdf_creation_date.hpp>

#include "process.hpp"

namespace {

using kit::test::slurp;

// The creation date as the PDF holds it: in plain text (cairo 1.16) or in a compressed object
// stream (cairo 1.18); "" when there is none.
std::string creation_date(const std::string& pdf) {
  static const std::regex date(R"(/CreationDate \(D:([^)]*)\))");
  std::smatch m;
  if (std::regex_search(pdf, m, date)) return m[1];
  static const std::regex object_stream(R"(/Type /ObjStm[^>]*>>\nstream\n)");
  for (auto it = std::sregex_iterator(pdf.begin(), pdf.end(), object_stream); it != std::sregex_iterator();
       ++it) {
    const auto data = std::size_t(it->position() + it->length());
    const std::string plain =
        kit::pdf_inflate(std::string_view(pdf).substr(data, pdf.find("\nendstream", data) - data));
    if (std::regex_search(plain, m, date)) return m[1];
  }
  return "";
}

// Every byte offset the PDF's cross-reference gives (a classic table or a stream with /W [a b c])
// and startxref point at the object they name. Returns the offsets that do not.
std::vector<std::string> wrong_offsets(const std::string& pdf) {
  std::vector<std::string> wrong;
  const auto startxref = std::stoul(pdf.substr(pdf.rfind("startxref") + 9));
  auto at_object = [&](std::size_t offset, std::size_t number) {
    const std::string header = std::to_string(number) + " 0 obj";
    if (pdf.compare(offset, header.size(), header) != 0)
      wrong.push_back(header + " is not at " + std::to_string(offset));
  };
  std::smatch m;
  if (pdf.compare(startxref, 4, "xref") == 0) {  // classic: "xref\n0 N\n" then N lines of 20 bytes
    const std::string section = pdf.substr(startxref, 64);
    if (!std::regex_search(section, m, std::regex(R"(xref\s+0 (\d+)\s+)"))) return {"no xref section"};
    const std::size_t rows = std::stoul(m[1].str()), first = startxref + std::size_t(m.length());
    for (std::size_t k = 1; k < rows; ++k)
      if (pdf[first + 20 * k + 17] == 'n') at_object(std::stoul(pdf.substr(first + 20 * k, 10)), k);
    return wrong;
  }
  const std::string dictionary = pdf.substr(startxref, pdf.find("stream", startxref) - startxref);
  if (!std::regex_search(dictionary, m, std::regex(R"(/W \[(\d) (\d) (\d)\])")))
    return {"no /W in the xref stream"};
  const std::size_t a = std::stoul(m[1].str()), b = std::stoul(m[2].str()),
                    row = a + b + std::stoul(m[3].str());
  const auto data = pdf.find("\nstream\n", startxref) + 8;
  const std::string table =
      kit::pdf_inflate(std::string_view(pdf).substr(data, pdf.find("\nendstream", data) - data));
  auto field = [&](std::size_t r, std::size_t at, std::size_t width) {
    std::size_t value = 0;
    for (std::size_t i = 0; i < width; ++i)
      value = value << 8 | static_cast<unsigned char>(table[r * row + at + i]);
    return value;
  };
  for (std::size_t k = 0; k < table.size() / row; ++k)
    if ((a == 0 ? 1 : field(k, 0, a)) == 1) at_object(field(k, a, b), k);
  return wrong;
}

// A PDF laid out as cairo 1.18 writes one: the document information (object 5) in a compressed
// object stream (3) whose length is object 4, behind it, then a compressed cross-reference stream.
std::string cairo_118_pdf(const std::string& date) {
  std::string pdf = "%PDF-1.7\n%\xb5\xed\xae\xfb\n";
  std::vector<std::size_t> offset(7, 0);
  offset[1] = pdf.size();
  pdf += "1 0 obj\n<< /Type /Catalog /Pages 2 0 R >>\nendobj\n";
  offset[2] = pdf.size();
  pdf += "2 0 obj\n<< /Type /Pages /Kids [ ] /Count 0 >>\nendobj\n";
  const std::string info =
      "5 0\n<< /Producer (cairo 1.18.4 (https://cairographics.org))\n   /CreationDate (D:" + date + ")\n>>\n";
  const std::string objects = kit::pdf_deflate(info);
  offset[3] = pdf.size();
  pdf += "3 0 obj\n<< /Type /ObjStm\n   /Length 4 0 R\n   /N 1\n   /First 4\n   /Filter "
         "/FlateDecode\n>>\nstream\n" +
         objects + "\nendstream\nendobj\n";
  offset[4] = pdf.size();
  pdf += "4 0 obj\n   " + std::to_string(objects.size()) + "\nendobj\n";
  offset[6] = pdf.size();
  std::string table;
  for (std::size_t k = 0; k < 7; ++k) {
    const int type = k == 0 ? 0 : k == 5 ? 2 : 1;
    const std::size_t second = k == 5 ? 3 : offset[k], third = 0;
    table += char(type);
    table += char(second >> 8);
    table += char(second & 0xff);
    table += char(third >> 8);
    table += char(third & 0xff);
  }
  const std::string xref = kit::pdf_deflate(table);
  pdf +=
      "6 0 obj\n<< /Type /XRef\n   /Length " + std::to_string(xref.size()) +
      "\n   /Filter /FlateDecode\n   /Size 7\n   /W [1 2 2]\n   /Root 1 0 R\n   /Info 5 0 R\n>>\nstream\n" +
      xref + "\nendstream\nendobj\nstartxref\n" + std::to_string(offset[6]) + "\n%%EOF\n";
  return pdf;
}

}  // namespace

TEST_CASE("a plain creation date (cairo 1.16) becomes SOURCE_DATE_EPOCH's, keeping its length") {
  const std::string pdf =
      "%PDF-1.5\n1 0 obj\n<< /Producer (cairo 1.16.0) /CreationDate (D:20261127081022Z) >>\nendobj\n";
  const auto pinned = kit::with_pdf_creation_date(pdf, 86400);
  REQUIRE(pinned);
  CHECK(creation_date(*pinned) == "19700102000000Z");
  CHECK(pinned->size() == pdf.size());
  // The other forms of the zone keep their length too.
  CHECK(creation_date(*kit::with_pdf_creation_date("/CreationDate (D:20261127081022+01'00)", 0)) ==
        "19700101000000+00'00");
  CHECK(creation_date(*kit::with_pdf_creation_date("/CreationDate (D:20261127081022+01'00')", 0)) ==
        "19700101000000+00'00'");
  CHECK_FALSE(kit::with_pdf_creation_date("/CreationDate (D:2026)", 0));  // a form it does not know
}

TEST_CASE("a compressed creation date (cairo 1.18) is set, and every offset behind it moves with it") {
  const std::string pdf = cairo_118_pdf("20261127081022Z");
  REQUIRE(wrong_offsets(pdf).empty());  // the sample itself is right
  const auto pinned = kit::with_pdf_creation_date(pdf, 0);
  REQUIRE(pinned);
  CHECK(creation_date(*pinned) == "19700101000000Z");
  // The epoch's date compresses otherwise than the clock's: the object stream changed length, so
  // the length object, the cross-reference stream and startxref all had to move.
  CHECK(pinned->size() != pdf.size());
  CHECK(wrong_offsets(*pinned).empty());
  // The length object holds the object stream's new length.
  const auto data = pinned->find("stream\n") + 7, end = pinned->find("\nendstream", data);
  CHECK(pinned->find("4 0 obj\n   " + std::to_string(end - data) + "\n") != std::string::npos);
  // Pinning twice gives the same bytes.
  CHECK(kit::with_pdf_creation_date(*pinned, 0) == pinned);
}

TEST_CASE("a PDF whose object stream has no length it can read is left alone, without throwing") {
  std::string pdf = cairo_118_pdf("20261127081022Z");
  const auto length = pdf.find("4 0 obj\n   ");
  REQUIRE(length != std::string::npos);
  pdf[length + 11] = 'x';  // the length object no longer starts with a digit
  CHECK_FALSE(kit::with_pdf_creation_date(pdf, 0));
  CHECK_FALSE(kit::with_pdf_creation_date("/Type /ObjStm /Length 4 0 R >>\nstream\n", 0));
}

TEST_CASE("a figure's PDF rendered by this system's gnuplot and cairo gets SOURCE_DATE_EPOCH's date") {
  kit::test::TempDir dir("pdf-date");
  kit::FigureOptions options;
  options.dir = dir.path();
  options.formats = {"pdf"};
  kit::Figure fig("dated", "A dated figure");
  fig.panel("time t [s]", "height x [m]", "").line("line", {0, 1}, {0, 1});
  const char* before = std::getenv("SOURCE_DATE_EPOCH");
  const std::string saved = before ? before : "";
  setenv("SOURCE_DATE_EPOCH", "1000000000", 1);  // 2001-09-09 01:46:40 UTC
  kit::write_figure(fig, options);
  before ? setenv("SOURCE_DATE_EPOCH", saved.c_str(), 1) : unsetenv("SOURCE_DATE_EPOCH");
  const std::string pdf = slurp(dir.path() / "dated.pdf");
  CHECK(creation_date(pdf).substr(0, 14) == "20010909014640");
  CHECK(wrong_offsets(pdf).empty());
}
