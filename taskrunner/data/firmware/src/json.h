// The little JSON the firmware needs: read {"cmd": "..."} from an HTTP body, quote a
// string for a reply, and (for tests) check that a document is well-formed JSON.
#pragma once

#include <string>
#include <string_view>

namespace trs {

// Reads the string member "cmd" of the JSON object `body` (other members are skipped;
// if "cmd" appears twice the last one wins). On failure returns false and sets `error`
// to a message such as "'cmd' must be a string (got number)".
bool json_extract_cmd(std::string_view body, std::string* cmd, std::string* error);

// `text` as a JSON string literal, quotes included; control bytes become \u00XX.
std::string json_quote(std::string_view text);

// True when `text` is exactly one well-formed JSON value (surrounding whitespace allowed).
bool json_valid(std::string_view text);

}  // namespace trs
