#pragma once
// Text put into HTML or XML (the report page, the VTK files): & < > " as entities.

#include <string>

namespace grainlab {

inline std::string markupEscaped(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

} // namespace grainlab
