// CSV lines (internal to io/): io/csv_table.h splits every CSV file's lines here, so the sites,
// the reported sensors and the map generator's town lists take the same files.
//
// Delimiter: the one of comma, semicolon, tab and '|' that splits the header line into the most
// fields (outside double quotes); a comma when none splits it. Spreadsheets in much of Europe
// write semicolons, because their decimal separator is the comma; with any delimiter other than a
// comma, a number written with a decimal comma ("7,4508") is read as with a point.
// Fields: trimmed of spaces (and of tabs, unless the tab is the delimiter); a field may be
// double-quoted to hold the delimiter or surrounding spaces, "" standing for one quote inside.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace covmap::io::detail {

enum class CsvDelimiter : char { kComma = ',', kSemicolon = ';', kTab = '\t', kPipe = '|' };

CsvDelimiter detect_delimiter(std::string_view header_line);

// "comma", "semicolon", "tab", "'|'": for messages.
std::string_view delimiter_name(CsvDelimiter delimiter);

struct CsvFields {
  std::vector<std::string> values;
  std::string error;  // non-empty if the line could not be split: an open quote, text after one
};

CsvFields split_csv_line(std::string_view line, CsvDelimiter delimiter);

// The field as a number's text for from_chars: with a delimiter other than the comma, a field of
// digits holding one comma and no point has the comma read as the decimal point ("7,45" → "7.45");
// anything else is returned as it is.
std::string number_text(std::string_view field, CsvDelimiter delimiter);

}  // namespace covmap::io::detail
