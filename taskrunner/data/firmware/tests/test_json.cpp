#include <string>

#include "../src/json.h"
#include "harness.h"

namespace {
std::string cmd_of(std::string_view body) {
  std::string cmd;
  std::string error;
  if (!trs::json_extract_cmd(body, &cmd, &error)) return "ERROR: " + error;
  return cmd;
}
}  // namespace

TEST(json_extract_cmd_reads_the_cmd_member) {
  CHECK_EQ(cmd_of(R"({"cmd": "STATUS"})"), "STATUS");
  CHECK_EQ(cmd_of(R"(  {"cmd":"MOVE:90,90,90,90,90,90"}  )"), "MOVE:90,90,90,90,90,90");
  CHECK_EQ(cmd_of(R"({"id": 3, "cmd": "PING", "x": [1, {"y": null}], "z": true})"), "PING");
  CHECK_EQ(cmd_of(R"({"cmd": "A", "cmd": "B"})"), "B");
  CHECK_EQ(cmd_of("{\"cmd\":\"\"}"), "");
}

TEST(json_extract_cmd_decodes_escapes) {
  CHECK_EQ(cmd_of(R"({"cmd": "a\"b\\c\/d"})"), "a\"b\\c/d");
  CHECK_EQ(cmd_of(R"({"cmd": "\u0050ING"})"), "PING");
  CHECK_EQ(cmd_of(R"({"cmd": "x\ny"})"), "x\ny");
  CHECK_EQ(cmd_of(R"({"cmd": "\u00e9"})"), "\xc3\xa9");
  CHECK_EQ(cmd_of(R"({"cmd": "\ud83d\ude00"})"), "\xf0\x9f\x98\x80");
}

TEST(json_extract_cmd_explains_what_is_wrong) {
  CHECK_EQ(cmd_of(R"({"cmd": 5})"), "ERROR: 'cmd' must be a string (got number)");
  CHECK_EQ(cmd_of(R"({"cmd": ["PING"]})"), "ERROR: 'cmd' must be a string (got array)");
  CHECK_EQ(cmd_of(R"({"cmd": null})"), "ERROR: 'cmd' must be a string (got null)");
  CHECK(cmd_of(R"({"command": "PING"})").rfind("ERROR: missing 'cmd'", 0) == 0);
  CHECK(cmd_of("[]").rfind("ERROR: body must be a JSON object", 0) == 0);
  CHECK(cmd_of("").rfind("ERROR: body must be a JSON object", 0) == 0);
  CHECK(cmd_of("STATUS").rfind("ERROR: body must be a JSON object", 0) == 0);
  CHECK(cmd_of(R"({"cmd": "PING"} x)").rfind("ERROR: unexpected data", 0) == 0);
  CHECK(cmd_of(R"({"cmd": "PING")").rfind("ERROR: malformed JSON", 0) == 0);
  CHECK(cmd_of(R"({"cmd": "PI)").rfind("ERROR: malformed JSON", 0) == 0);
  CHECK(cmd_of(R"({"cmd" "PING"})").rfind("ERROR: malformed JSON", 0) == 0);
  CHECK(cmd_of("{\"cmd\": \"a\x01\"}").rfind("ERROR: malformed JSON", 0) == 0);
  CHECK(cmd_of(R"({"cmd": "\ud83d"})").rfind("ERROR: malformed JSON", 0) == 0);
  CHECK(cmd_of(R"({"cmd": "\q"})").rfind("ERROR: malformed JSON", 0) == 0);
  CHECK(cmd_of(R"({"a": 01, "cmd": "PING"})").rfind("ERROR: malformed JSON", 0) == 0);
}

TEST(json_extract_cmd_limits_nesting) {
  std::string deep = "{\"a\":";
  for (int i = 0; i < 10000; ++i) deep += "[";
  CHECK(cmd_of(deep).rfind("ERROR: malformed JSON", 0) == 0);
}

TEST(json_quote_escapes_quotes_backslashes_and_controls) {
  CHECK_EQ(trs::json_quote("ok"), "\"ok\"");
  CHECK_EQ(trs::json_quote("a\"b\\c"), "\"a\\\"b\\\\c\"");
  CHECK_EQ(trs::json_quote(std::string("\n\x01", 2)), "\"\\u000a\\u0001\"");
  CHECK(trs::json_valid(trs::json_quote("ok {\"status\":\"ok\",\"pos\":[90]}")));
}

TEST(json_valid_accepts_json_and_rejects_the_rest) {
  CHECK(trs::json_valid(R"({"a":[1,-2.5,3e4,true,false,null,"x",{}]})"));
  CHECK(trs::json_valid(" 0 "));
  CHECK(!trs::json_valid("{"));
  CHECK(!trs::json_valid("{} {}"));
  CHECK(!trs::json_valid("[1,]"));
  CHECK(!trs::json_valid("{\"a\":1,}"));
  CHECK(!trs::json_valid("-"));
  CHECK(!trs::json_valid("1."));
  CHECK(!trs::json_valid("tru"));
}
