#include <kit/app/pdf_creation_date.hpp>

#include <algorithm>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>
#include <boost/iostreams/device/back_inserter.hpp>
#include <boost/iostreams/filter/zlib.hpp>
#include <boost/iostreams/filtering_stream.hpp>

namespace kit {

namespace {

constexpr std::string_view kDateKey = "/CreationDate (D:";

// Sets the date that starts at `start` (after "(D:", up to the next ')') to `epoch`, keeping its
// length: YYYYMMDDHHmmSS then "Z" (cairo, UTC), "+00'00" or "+00'00'". False on any other form.
bool set_date(std::string& text, std::size_t start, long long epoch) {
  const auto close = text.find(')', start);
  if (close == std::string::npos) return false;
  const std::time_t seconds = std::time_t(epoch);
  std::tm utc{};
  gmtime_r(&seconds, &utc);
  const std::string stamp = fmt::format("{:04}{:02}{:02}{:02}{:02}{:02}", utc.tm_year + 1900, utc.tm_mon + 1,
                                        utc.tm_mday, utc.tm_hour, utc.tm_min, utc.tm_sec);
  const std::size_t length = close - start;
  const std::string date = length == 15   ? stamp + "Z"
                           : length == 20 ? stamp + "+00'00"
                           : length == 21 ? stamp + "+00'00'"
                                          : "";
  if (date.empty()) return false;
  text.replace(start, length, date);
  return true;
}

// A stream object as cairo writes it: "N 0 obj\n<< ... >>\nstream\n" DATA "\nendstream".
struct StreamObject {
  std::size_t dictionary = 0, dictionary_end = 0;  // the dictionary's text
  std::size_t data = 0, length = 0;                // the stream's bytes
  std::size_t length_at = 0, length_digits = 0;    // where its /Length number is written
};

// The stream object whose dictionary starts at or after `from`; nullopt if it is not one.
std::optional<StreamObject> stream_at(const std::string& pdf, std::size_t from) {
  StreamObject s;
  s.dictionary = pdf.find("<<", from);
  const auto keyword = pdf.find("\nstream\n", from);
  if (s.dictionary == std::string::npos || keyword == std::string::npos) return std::nullopt;
  s.dictionary_end = keyword;
  s.data = keyword + 8;
  const std::string dictionary = pdf.substr(s.dictionary, s.dictionary_end - s.dictionary);
  static const std::regex length_entry(R"(/Length (\d+)( 0 R)?)");
  std::smatch m;
  if (!std::regex_search(dictionary, m, length_entry)) return std::nullopt;
  if (!m[2].matched) {  // direct: the number is in the dictionary
    s.length_at = s.dictionary + std::size_t(m.position(1));
    s.length_digits = std::size_t(m.length(1));
  } else {  // indirect: "M 0 obj\n   NUMBER\nendobj", elsewhere in the file
    const std::string header = "\n" + m[1].str() + " 0 obj\n";
    auto at = pdf.find(header);
    if (at == std::string::npos) return std::nullopt;
    at = pdf.find_first_not_of(" \n\r", at + header.size());
    if (at == std::string::npos) return std::nullopt;
    const auto end = pdf.find_first_not_of("0123456789", at);
    if (end == std::string::npos) return std::nullopt;
    s.length_at = at;
    s.length_digits = end - at;
  }
  // No digits, or too many to be a length here: not a stream this knows (stoul would throw).
  if (s.length_digits == 0 || s.length_digits > 12) return std::nullopt;
  s.length = std::stoul(pdf.substr(s.length_at, s.length_digits));
  if (s.data + s.length > pdf.size()) return std::nullopt;
  return s;
}

// One replacement of the bytes [at, at + old_size) by `text`, in the original file's offsets.
struct Edit {
  std::size_t at = 0, old_size = 0;
  std::string text;
};

// Where the byte at `offset` of the original file lies once `edits` are made.
std::size_t moved(std::size_t offset, const std::vector<Edit>& edits) {
  std::ptrdiff_t shift = 0;
  for (const Edit& e : edits)
    if (e.at < offset) shift += std::ptrdiff_t(e.text.size()) - std::ptrdiff_t(e.old_size);
  return std::size_t(std::ptrdiff_t(offset) + shift);
}

std::string apply(std::string pdf, std::vector<Edit> edits) {
  std::sort(edits.begin(), edits.end(),
            [](const Edit& a, const Edit& b) { return a.at > b.at; });  // back to front
  for (const Edit& e : edits) pdf.replace(e.at, e.old_size, e.text);
  return pdf;
}

// The object stream `objects` gets `data` (compressed): its bytes and its /Length change, and the
// cross-reference stream (cairo 1.18 writes one, /W [a b c], no predictor) moves every offset
// behind them, as does startxref.
std::optional<std::string> replace_stream(const std::string& pdf, const StreamObject& objects,
                                          std::string data) {
  std::vector<Edit> edits{{objects.data, objects.length, data},
                          {objects.length_at, objects.length_digits, std::to_string(data.size())}};
  const auto startxref = pdf.rfind("startxref");
  if (startxref == std::string::npos) return std::nullopt;
  const auto number = pdf.find_first_of("0123456789", startxref);
  const auto number_end = pdf.find_first_not_of("0123456789", number);
  const std::size_t xref_offset = std::stoul(pdf.substr(number, number_end - number));
  const auto xref = stream_at(pdf, xref_offset);
  if (!xref || xref->data <= objects.data) return std::nullopt;
  const std::string dictionary = pdf.substr(xref->dictionary, xref->dictionary_end - xref->dictionary);
  static const std::regex widths(R"(/W \[(\d) (\d) (\d)\])");
  std::smatch w;
  if (dictionary.find("/Type /XRef") == std::string::npos ||
      dictionary.find("/DecodeParms") != std::string::npos || !std::regex_search(dictionary, w, widths) ||
      xref->length_at < xref->dictionary || xref->length_at > xref->data)
    return std::nullopt;  // not the cross-reference stream cairo writes
  const std::size_t type_width = std::stoul(w[1].str()), offset_width = std::stoul(w[2].str());
  const std::size_t row = type_width + offset_width + std::stoul(w[3].str());
  std::string table = pdf_inflate(std::string_view(pdf).substr(xref->data, xref->length));
  if (row == 0 || table.size() % row != 0) return std::nullopt;
  for (std::size_t r = 0; r < table.size(); r += row) {
    auto field = [&](std::size_t at, std::size_t width) {
      std::size_t value = 0;
      for (std::size_t i = 0; i < width; ++i)
        value = value << 8 | static_cast<unsigned char>(table[r + at + i]);
      return value;
    };
    if ((type_width == 0 ? 1 : field(0, type_width)) != 1) continue;  // only type 1 rows hold a byte offset
    std::size_t offset = moved(field(type_width, offset_width), edits);
    if (offset_width < sizeof(std::size_t) && offset >> (8 * offset_width) != 0)
      return std::nullopt;  // no room
    for (std::size_t i = offset_width; i-- > 0; offset >>= 8) table[r + type_width + i] = char(offset & 0xff);
  }
  const std::size_t new_xref_offset = moved(xref_offset, edits);
  std::string compressed = pdf_deflate(table);
  edits.push_back({xref->length_at, xref->length_digits, std::to_string(compressed.size())});
  edits.push_back({xref->data, xref->length, std::move(compressed)});
  edits.push_back({number, number_end - number, std::to_string(new_xref_offset)});
  return apply(pdf, std::move(edits));
}

}  // namespace

std::string pdf_inflate(std::string_view compressed) {
  namespace io = boost::iostreams;
  std::string plain;
  try {
    io::filtering_ostream out;
    out.push(io::zlib_decompressor());
    out.push(io::back_inserter(plain));
    out.write(compressed.data(), std::streamsize(compressed.size()));
    out.reset();
  } catch (const std::exception& e) {
    throw std::runtime_error(std::string("not a zlib stream: ") + e.what());
  }
  return plain;
}

std::string pdf_deflate(std::string_view plain) {
  namespace io = boost::iostreams;
  std::string compressed;
  io::filtering_ostream out;
  out.push(io::zlib_compressor());
  out.push(io::back_inserter(compressed));
  out.write(plain.data(), std::streamsize(plain.size()));
  out.reset();
  return compressed;
}

std::optional<std::string> with_pdf_creation_date(std::string pdf, long long epoch) {
  // cairo 1.16: the document information in plain text; the date keeps its length.
  if (const auto at = pdf.find(kDateKey); at != std::string::npos)
    return set_date(pdf, at + kDateKey.size(), epoch) ? std::optional<std::string>(std::move(pdf))
                                                      : std::nullopt;
  // cairo 1.18: in a compressed object stream.
  for (auto at = pdf.find("/Type /ObjStm"); at != std::string::npos; at = pdf.find("/Type /ObjStm", at + 1)) {
    const auto object = pdf.rfind(" obj", at);
    const auto objects = object == std::string::npos ? std::nullopt : stream_at(pdf, object);
    if (!objects) return std::nullopt;
    std::string plain;
    try {
      plain = pdf_inflate(std::string_view(pdf).substr(objects->data, objects->length));
    } catch (const std::runtime_error&) {
      return std::nullopt;
    }
    const auto key = plain.find(kDateKey);
    if (key == std::string::npos) continue;
    if (!set_date(plain, key + kDateKey.size(), epoch)) return std::nullopt;
    try {
      return replace_stream(pdf, *objects, pdf_deflate(plain));
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  return std::nullopt;
}

void pin_pdf_creation_date(const std::filesystem::path& pdf) {
  const char* epoch_text = std::getenv("SOURCE_DATE_EPOCH");
  if (!epoch_text) return;
  char* end = nullptr;
  const long long epoch = std::strtoll(epoch_text, &end, 10);
  if (end == epoch_text || *end != '\0' || epoch < 0 || epoch > 253402300799LL) return;  // up to year 9999
  std::ifstream in(pdf, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  in.close();
  if (const auto pinned = with_pdf_creation_date(bytes.str(), epoch))
    std::ofstream(pdf, std::ios::binary | std::ios::trunc) << *pinned;
}

}  // namespace kit
