// Reproducible figure PDFs: the creation date cairo writes, replaced by SOURCE_DATE_EPOCH's.
//
// gnuplot's pdfcairo terminal writes the clock's time as the document's /CreationDate, so two
// renders of one figure differ. cairo 1.16 (Debian 12) writes it in plain text; cairo 1.18
// (Debian 13) packs the document information into a compressed object stream, indexed by a
// compressed cross-reference stream. Both forms are handled: the date keeps its length, and where
// it sat in a compressed stream, that stream is compressed again and every byte offset behind it
// (the cross-reference stream's entries, startxref) is moved by the change in length.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace kit {

// `pdf` (a whole file's bytes) with its creation date set to `epoch` [s since 1970, UTC]; nullopt
// when the file has no creation date in a form this knows (it is then best left as it is).
std::optional<std::string> with_pdf_creation_date(std::string pdf, long long epoch);

// Rewrites the file at `pdf` in place when SOURCE_DATE_EPOCH holds a time from 1970 to 9999;
// otherwise, or when the file's form is unknown, leaves it alone.
void pin_pdf_creation_date(const std::filesystem::path& pdf);

// zlib's inflate and deflate (FlateDecode), as PDF streams use them; inflate throws
// std::runtime_error on data that is not a zlib stream.
std::string pdf_inflate(std::string_view compressed);
std::string pdf_deflate(std::string_view plain);

}  // namespace kit
