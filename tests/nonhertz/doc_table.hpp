// Deterministic tables of doc/validation/non-hertzian.md are made by the
// tests that compute them: the page holds each between
//   <!-- table: NAME --> ... <!-- end table: NAME -->
// and check_doc_table fails when the page and the computed table differ.
// CW_WRITE_DOC_TABLES=1 writes the computed table into the page instead.
#pragma once

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace cwtest {

// "" when the page's table equals text (or was just written), else why not.
inline std::string check_doc_table(const std::string& page, const std::string& name,
                                   const std::string& text)
{
    std::ifstream in(page);
    if (!in) return "cannot read " + page;
    std::stringstream all;
    all << in.rdbuf();
    std::string doc = all.str();
    const std::string open = "<!-- table: " + name + " -->\n";
    const std::string close = "<!-- end table: " + name + " -->";
    const size_t a = doc.find(open), b = doc.find(close);
    if (a == std::string::npos || b == std::string::npos || b < a)
        return page + " has no block " + open.substr(0, open.size() - 1);
    const size_t from = a + open.size();
    if (doc.compare(from, b - from, text) == 0) return "";
    if (std::getenv("CW_WRITE_DOC_TABLES")) {
        doc.replace(from, b - from, text);
        std::ofstream(page) << doc;
        return "";
    }
    return page + ": table " + name + " differs from the computed one (run the test with "
                                      "CW_WRITE_DOC_TABLES=1 to write it):\n" + text;
}

} // namespace cwtest
