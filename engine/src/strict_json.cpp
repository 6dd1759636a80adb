#include "grainlab/strict_json.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

namespace grainlab {

JsonFileError::JsonFileError(std::string file_, std::string keyPath_, const std::string& message)
    : std::runtime_error(file_ + ": " + message), file(std::move(file_)),
      keyPath(std::move(keyPath_)) {}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::size_t editDistance(const std::string& a, const std::string& b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) {
        row[j] = j;
    }
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t above = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
            diagonal = above;
        }
    }
    return row[b.size()];
}

} // namespace

bool Range::contains(double v) const {
    const bool aboveLo = loClosed ? v >= lo : v > lo;
    const bool belowHi = hiClosed ? v <= hi : v < hi;
    return aboveLo && belowHi;
}

std::string Range::text() const {
    if (hi == kInf) {
        return fmt::format("{} {}", loClosed ? ">=" : ">", lo);
    }
    return fmt::format("in {}{}, {}{}", loClosed ? "[" : "(", lo, hi, hiClosed ? "]" : ")");
}

Range positive() {
    return {0.0, kInf, false, false};
}
Range nonNegative() {
    return {0.0, kInf, true, false};
}
Range openClosed(double lo, double hi) {
    return {lo, hi, false, true};
}
Range open(double lo, double hi) {
    return {lo, hi, false, false};
}
Range closed(double lo, double hi) {
    return {lo, hi, true, true};
}

std::string joinPath(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

/// The value as written in JSON, shortened for messages.
std::string showValue(const Json& v) {
    std::string s = v.dump();
    if (s.size() > 60) {
        s = s.substr(0, 57) + "...";
    }
    return s;
}

std::string jsonTypeName(const Json& v) {
    switch (v.type()) {
    case Json::value_t::null:
        return "null";
    case Json::value_t::boolean:
        return "a boolean";
    case Json::value_t::string:
        return "a string";
    case Json::value_t::array:
        return "an array";
    case Json::value_t::object:
        return "an object";
    default:
        return "a number";
    }
}

JsonSection::JsonSection(const std::string& file, const Json& node, std::string path,
                         std::vector<std::string> known)
    : file_(file), node_(node), path_(std::move(path)), known_(std::move(known)) {
    if (!node_.is_object()) {
        // The top level has no key to name: say so in words.
        throw JsonFileError(
            file_, path_,
            path_.empty()
                ? fmt::format("the file must hold one object {{...}} at its top level (got {}: "
                              "{})",
                              jsonTypeName(node_), showValue(node_))
                : fmt::format("{} = {}: must be an object {{...}} (got {})", path_,
                              showValue(node_), jsonTypeName(node_)));
    }
    for (const auto& item : node_.items()) {
        if (std::find(known_.begin(), known_.end(), item.key()) == known_.end()) {
            refuseUnknown(item.key());
        }
    }
}

void JsonSection::fail(const std::string& key, const std::string& message) const {
    throw JsonFileError(file_, path(key), message);
}
void JsonSection::refuse(const std::string& key, const Json& value,
                         const std::string& allowed) const {
    fail(key, fmt::format("{} = {}: must be {}", path(key), showValue(value), allowed));
}
void JsonSection::missing(const std::string& key, const std::string& allowed) const {
    fail(key, fmt::format("missing required key {} ({})", path(key), allowed));
}

namespace {

/// The value of `key` in `s` when it is there and of the JSON type `typed` accepts; nullptr when
/// absent, for `fallback` to answer (a required key is refused as missing). `allowed` says what
/// may stand there.
template <class T>
const Json* givenValue(const JsonSection& s, const std::string& key,
                       const std::optional<T>& fallback, const std::string& allowed,
                       bool (Json::*typed)() const noexcept) {
    if (!s.has(key)) {
        if (!fallback) {
            s.missing(key, allowed);
        }
        return nullptr;
    }
    const Json& v = s.at(key);
    if (!(v.*typed)()) {
        s.refuse(key, v, fmt::format("{} (got {})", allowed, jsonTypeName(v)));
    }
    return &v;
}

} // namespace

double JsonSection::number(const std::string& key, Range range,
                           std::optional<double> fallback) const {
    const std::string allowed = "a number " + range.text();
    const Json* v = givenValue(*this, key, fallback, allowed, &Json::is_number);
    if (!v) {
        return *fallback;
    }
    const double x = v->get<double>();
    if (!std::isfinite(x) || !range.contains(x)) {
        refuse(key, *v, allowed);
    }
    return x;
}

std::int64_t JsonSection::integer(const std::string& key, std::int64_t lo, std::int64_t hi,
                                  std::optional<std::int64_t> fallback) const {
    // Bounds that only keep the value representable are not worth a reader's attention.
    const std::string allowed = hi == std::numeric_limits<std::int64_t>::max()
                                    ? fmt::format("an integer >= {}", lo)
                                : hi >= std::numeric_limits<std::int32_t>::max()
                                    ? fmt::format("an integer >= {} (at most {})", lo, hi)
                                    : fmt::format("an integer in [{}, {}]", lo, hi);
    const Json* given = givenValue(*this, key, fallback, allowed, &Json::is_number);
    if (!given) {
        return *fallback;
    }
    const Json& v = *given;
    std::int64_t n = 0;
    if (v.is_number_unsigned()) {
        const auto u = v.get<std::uint64_t>();
        if (u > static_cast<std::uint64_t>(hi)) {
            refuse(key, v, allowed);
        }
        n = static_cast<std::int64_t>(u);
    } else if (v.is_number_integer()) {
        n = v.get<std::int64_t>();
    } else {
        const double x = v.get<double>();
        // Exact integers only; the bound keeps the conversion defined.
        if (!(std::fabs(x) < 9.0e18) || std::floor(x) != x) {
            refuse(key, v, allowed);
        }
        n = static_cast<std::int64_t>(x);
    }
    if (n < lo || n > hi) {
        refuse(key, v, allowed);
    }
    return n;
}

std::string JsonSection::choice(const std::string& key, const std::vector<std::string>& allowed,
                                std::optional<std::string> fallback) const {
    std::string list;
    for (const auto& a : allowed) {
        list += (list.empty() ? "" : ", ") + ("\"" + a + "\"");
    }
    const std::string text = "one of " + list;
    const Json* v = givenValue(*this, key, fallback, text, &Json::is_string);
    if (!v) {
        return *fallback;
    }
    const auto s = v->get<std::string>();
    if (std::find(allowed.begin(), allowed.end(), s) == allowed.end()) {
        refuse(key, *v, text);
    }
    return s;
}

std::string JsonSection::text(const std::string& key, const std::string& fallback) const {
    if (!has(key)) {
        return fallback;
    }
    const Json& v = at(key);
    if (!v.is_string() || v.get<std::string>().empty()) {
        refuse(key, v, fmt::format("a non-empty string (got {})", jsonTypeName(v)));
    }
    return v.get<std::string>();
}

std::optional<std::vector<double>> JsonSection::numbers(const std::string& key, Range range) const {
    if (!has(key)) {
        return std::nullopt;
    }
    const Json& v = at(key);
    const std::string allowed = "a non-empty array of numbers " + range.text();
    if (!v.is_array() || v.empty()) {
        refuse(
            key, v,
            fmt::format("{} (got {})", allowed, v.is_array() ? "an empty array" : jsonTypeName(v)));
    }
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size(); ++i) {
        const Json& e = v[i];
        const std::string element = fmt::format("{}[{}]", key, i);
        if (!e.is_number()) {
            refuse(element, e, fmt::format("a number {} (got {})", range.text(), jsonTypeName(e)));
        }
        const double x = e.get<double>();
        if (!std::isfinite(x) || !range.contains(x)) {
            refuse(element, e, "a number " + range.text());
        }
        out.push_back(x);
    }
    return out;
}

JsonSection JsonSection::child(const std::string& key, std::vector<std::string> known,
                               bool required, const std::string& requiredWhat) const {
    static const Json kEmpty = Json::object();
    if (!has(key)) {
        if (required) {
            missing(key, requiredWhat);
        }
        return JsonSection(file_, kEmpty, path(key), std::move(known));
    }
    return JsonSection(file_, at(key), path(key), std::move(known));
}

std::vector<JsonSection> JsonSection::objects(const std::string& key,
                                              const std::vector<std::string>& known) const {
    std::vector<JsonSection> out;
    if (!has(key)) {
        return out;
    }
    const Json& value = at(key);
    if (value.is_array()) {
        if (value.empty()) {
            refuse(key, value, "an object or a non-empty array of objects");
        }
        for (std::size_t k = 0; k < value.size(); ++k) {
            out.emplace_back(file_, value[k], fmt::format("{}[{}]", path(key), k), known);
        }
        return out;
    }
    out.emplace_back(file_, value, path(key), known);
    return out;
}

void JsonSection::refuseUnknown(const std::string& key) const {
    std::string nearest;
    std::size_t best = std::max<std::size_t>(2, key.size() / 3) + 1;
    std::string list;
    for (const auto& k : known_) {
        list += (list.empty() ? "" : ", ") + k;
        const std::size_t d = editDistance(key, k);
        if (d < best) {
            best = d;
            nearest = k;
        }
    }
    const std::string where = path_.empty() ? "at the top level" : "in " + path_;
    // A key "" has no name to show: name the empty string and where it is.
    const std::string shown =
        key.empty() ? fmt::format("\"\" (an empty key name) {}", where) : path(key);
    fail(key,
         fmt::format("unknown key {}{}; the keys allowed {} are: {}", shown,
                     nearest.empty() ? "" : " (did you mean " + path(nearest) + "?)", where, list));
}

Json parseStrictJson(const std::string& text, const std::string& file) {
    struct Frame {
        bool object;
        std::string path;
        std::set<std::string> keys;
        std::string lastKey;
        std::size_t index = 0;
    };
    std::vector<Frame> stack;
    std::string duplicate;
    const auto childPath = [&]() -> std::string {
        if (stack.empty()) {
            return "";
        }
        const Frame& f = stack.back();
        return f.object ? joinPath(f.path, f.lastKey) : fmt::format("{}[{}]", f.path, f.index);
    };
    const auto nextElement = [&] {
        if (!stack.empty() && !stack.back().object) {
            ++stack.back().index;
        }
    };
    using Event = Json::parse_event_t;
    const Json::parser_callback_t callback = [&](int, Event event, Json& parsed) {
        switch (event) {
        case Event::object_start:
        case Event::array_start: {
            std::string p = childPath();
            if (stack.size() >= std::size_t(kMaxJsonNesting)) {
                // Refused as soon as it is seen: parsing a deeper file would cost memory
                // growing with the square of its depth. Blamed on the innermost key.
                std::string key;
                for (std::size_t i = stack.size() - 1; i >= 1 && key.empty(); --i) {
                    if (stack[i - 1].object) {
                        key = stack[i].path;
                    }
                }
                throw JsonFileError(file, key,
                                    fmt::format("{}: nesting deeper than {} levels of objects "
                                                "and arrays (no value of the file needs more "
                                                "than a few)",
                                                key.empty() ? "the file" : key, kMaxJsonNesting));
            }
            stack.push_back({event == Event::object_start, std::move(p), {}, {}, 0});
            break;
        }
        case Event::key: {
            Frame& f = stack.back();
            f.lastKey = parsed.get<std::string>();
            if (!f.keys.insert(f.lastKey).second && duplicate.empty()) {
                duplicate = joinPath(f.path, f.lastKey);
            }
            break;
        }
        case Event::object_end:
        case Event::array_end:
            stack.pop_back();
            nextElement();
            break;
        case Event::value:
            nextElement();
            break;
        }
        return true;
    };
    // JSON text holds no NUL byte (RFC 8259 allows none outside a string, and a string must
    // escape it as \u0000); the parser would stop at it and accept whatever follows unread.
    if (const std::size_t nul = text.find('\0'); nul != std::string::npos) {
        std::size_t line = 1, column = 1;
        for (std::size_t i = 0; i < nul; ++i) {
            column = text[i] == '\n' ? 1 : column + 1;
            line += text[i] == '\n';
        }
        throw JsonFileError(
            file, "",
            fmt::format("a NUL byte (0x00) at line {}, column {} (byte {}): a JSON text holds "
                        "none; the file is damaged or not text",
                        line, column, nul + 1));
    }
    Json root;
    try {
        root = Json::parse(text, callback, true, false);
    } catch (const Json::parse_error& e) {
        // Line and column of the byte where parsing failed (1-based).
        std::size_t line = 1, column = 1;
        const std::size_t end = std::min<std::size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
        for (std::size_t i = 0; i < end; ++i) {
            if (text[i] == '\n') {
                ++line;
                column = 1;
            } else {
                ++column;
            }
        }
        std::string detail = e.what();
        const auto colon = detail.find(": ", detail.find("column"));
        if (colon != std::string::npos) {
            detail = detail.substr(colon + 2);
        }
        throw JsonFileError(
            file, "",
            fmt::format("JSON syntax error at line {}, column {}: {}", line, column, detail));
    } catch (const Json::out_of_range& e) {
        // A number beyond the range of a double (1e309): the value of the key just read.
        const std::string key = childPath();
        std::string detail = e.what();
        const auto parsing = detail.find("parsing ");
        detail = parsing == std::string::npos ? detail : detail.substr(parsing + 8);
        throw JsonFileError(file, key,
                            fmt::format("{} = {}: a number beyond the range of a double (about "
                                        "+-1.8e308)",
                                        key.empty() ? "the file" : key, detail));
    } catch (const Json::exception& e) {
        throw JsonFileError(file, "", fmt::format("not valid JSON: {}", e.what()));
    }
    if (!duplicate.empty()) {
        throw JsonFileError(
            file, duplicate,
            fmt::format("duplicate key {}: each key may appear once per object", duplicate));
    }
    return root;
}

std::string readInputFile(const std::string& path, const std::string& what) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw JsonFileError(path, "",
                            fmt::format("is a folder, not an {}: give the path of the "
                                        ".json file",
                                        what));
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw JsonFileError(path, "",
                            fmt::format("cannot open the {} for reading ({})", what,
                                        std::filesystem::exists(path, error)
                                            ? "permission denied or not a regular file"
                                            : "no such file"));
    }
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) {
        throw JsonFileError(path, "", fmt::format("read error while reading the {}", what));
    }
    return text.str();
}

} // namespace grainlab
