#include "io/can/dbc/dbc_parser.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "io/can/dbc/dbc_semantics.h"
#include "io/config/input_file.h"

namespace rig::io::can::dbc {
namespace {

constexpr std::uint32_t kMaxMessageBytes = 64;
constexpr std::uint32_t kMaxSignalBits = 64;
constexpr std::uint32_t kExtendedFlag = 0x80000000u;
constexpr std::uint32_t kMaxCycleTimeMs = 3'600'000;

bool is_ident_start(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_'; }
bool is_ident_char(char c) { return is_ident_start(c) || (c >= '0' && c <= '9'); }
bool is_number_char(char c) {
  return (c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E' ||
         c == 'x' || c == 'X' || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
}

/// One attribute value as written: a string or a number token.
struct AttributeValue {
  std::string text;
  bool is_string = false;
  int line = 0;
};

/// Single-pass recursive-descent-free parser over the whole text. Every loop consumes at least
/// one character or ends, so work is linear in the input.
class Parser {
 public:
  Parser(std::string_view text, std::string_view file) : text_(text), file_(file) {
    db_.file = std::string(file);
  }

  Database run() {
    if (text_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;  // UTF-8 byte order mark
    while (true) {
      skip_space();
      if (eof()) break;
      const int line = line_;
      if (!is_ident_start(peek())) {
        fail(line, "expected a section keyword, found '" + printable(peek()) + "'");
      }
      const std::string keyword = identifier("a section keyword");
      if (keyword != "SG_") current_message_ = kNoMessage;
      if (keyword == "VERSION") {
        db_.version = string_literal();
      } else if (keyword == "NS_") {
        skip_new_symbols();
      } else if (keyword == "BS_") {
        skip_to_line_end();
      } else if (keyword == "BU_") {
        parse_nodes();
      } else if (keyword == "BO_") {
        parse_message(line);
      } else if (keyword == "SG_") {
        parse_signal(line);
      } else if (keyword == "CM_") {
        parse_comment(line);
      } else if (keyword == "BA_DEF_") {
        parse_attribute_definition();
      } else if (keyword == "BA_DEF_DEF_") {
        parse_attribute_default(line);
      } else if (keyword == "BA_") {
        parse_attribute(line);
      } else if (keyword == "VAL_") {
        parse_value_descriptions(line);
      } else if (keyword == "SIG_VALTYPE_") {
        parse_value_type(line);
      } else {
        warn(line, "section '" + keyword + "' is not supported, skipped");
        skip_statement();
      }
    }
    finish();
    return std::move(db_);
  }

 private:
  static constexpr std::size_t kNoMessage = std::numeric_limits<std::size_t>::max();

  // ---------------------------------------------------------------- errors
  [[noreturn]] void fail(int line, const std::string& what) const {
    throw config::ConfigError(std::string(file_) + ":" + std::to_string(line) + ": " + what);
  }
  void warn(int line, const std::string& what) {
    db_.warnings.push_back(std::string(file_) + ":" + std::to_string(line) + ": " + what);
  }
  static std::string printable(char c) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7F) return std::string(1, c);
    static constexpr char kHex[] = "0123456789abcdef";
    return std::string("\\x") + kHex[u >> 4] + kHex[u & 0xF];
  }
  static std::string clip(std::string_view s) {
    std::string out;
    for (char c : s.substr(0, 40)) out += printable(c);
    if (s.size() > 40) out += "...";
    return out;
  }

  // ---------------------------------------------------------------- lexing
  [[nodiscard]] bool eof() const { return pos_ >= text_.size(); }
  [[nodiscard]] char peek() const { return eof() ? '\0' : text_[pos_]; }
  void advance() {
    if (text_[pos_] == '\n') ++line_;
    ++pos_;
  }
  void skip_space() {
    while (!eof()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
        advance();
      } else {
        break;
      }
    }
  }
  void skip_inline_space() {
    while (!eof()) {
      const char c = text_[pos_];
      if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
        ++pos_;
      } else {
        break;
      }
    }
  }
  [[nodiscard]] bool at_line_end() {
    skip_inline_space();
    return eof() || peek() == '\n';
  }
  void skip_to_line_end() {
    while (!eof() && peek() != '\n') ++pos_;
  }
  /// NS_ : followed by indented symbol lines; ends at the first line that starts in column 0.
  void skip_new_symbols() {
    skip_to_line_end();
    while (!eof()) {
      advance();  // the '\n'
      if (eof()) break;
      const char c = peek();
      if (c != ' ' && c != '\t' && c != '\r' && c != '\n') break;
      skip_to_line_end();
    }
  }
  /// Skips up to and including the next ';' outside strings.
  void skip_statement() {
    while (!eof()) {
      const char c = peek();
      if (c == '"') {
        (void)string_literal();
        continue;
      }
      advance();
      if (c == ';') return;
    }
  }

  std::string identifier(const char* what) {
    skip_space();
    if (eof() || !is_ident_start(peek())) {
      fail(line_, std::string("expected ") + what + ", found " + found());
    }
    const std::size_t start = pos_;
    while (!eof() && is_ident_char(peek())) ++pos_;
    return std::string(text_.substr(start, pos_ - start));
  }
  std::string found() const {
    if (eof()) return "end of file";
    return "'" + printable(peek()) + "'";
  }
  void expect(char c, const char* context) {
    skip_space();
    if (peek() != c) {
      fail(line_, std::string("expected '") + c + "' " + context + ", found " + found());
    }
    advance();
  }
  bool accept(char c) {
    skip_space();
    if (peek() == c) {
      advance();
      return true;
    }
    return false;
  }
  std::string_view number_token() {
    skip_space();
    const std::size_t start = pos_;
    while (!eof() && is_number_char(peek())) ++pos_;
    return text_.substr(start, pos_ - start);
  }
  double real(const char* what) {
    const int line = line_;
    std::string_view token = number_token();
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty())
      fail(line, std::string("expected a number for ") + what + ", found " + found());
    if (ec != std::errc() || end != digits.data() + digits.size() || !std::isfinite(value)) {
      fail(line, std::string("bad number '") + clip(token) + "' for " + what);
    }
    return value;
  }
  std::uint64_t unsigned_integer(const char* what, std::uint64_t max) {
    skip_space();
    const int line = line_;
    const std::size_t start = pos_;
    while (!eof() && peek() >= '0' && peek() <= '9') ++pos_;
    const std::string_view token = text_.substr(start, pos_ - start);
    if (token.empty()) {
      fail(line, std::string("expected an unsigned integer for ") + what + ", found " + found());
    }
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    if (ec != std::errc() || end != token.data() + token.size() || value > max) {
      fail(line, std::string("bad ") + what + " '" + clip(token) + "' (at most " +
                     std::to_string(max) + ")");
    }
    return value;
  }
  std::int64_t signed_integer(const char* what) {
    const int line = line_;
    const std::string_view token = number_token();
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (token.empty())
      fail(line, std::string("expected an integer for ") + what + ", found " + found());
    if (ec != std::errc() || end != digits.data() + digits.size()) {
      fail(line, std::string("bad integer '") + clip(token) + "' for " + what);
    }
    return value;
  }
  /// A "..." string; `\"` and `\\` are escapes; may span lines.
  std::string string_literal() {
    skip_space();
    const int line = line_;
    if (peek() != '"') fail(line, "expected a string, found " + found());
    advance();
    std::string out;
    while (true) {
      if (eof()) fail(line, "unterminated string (opened here)");
      const char c = peek();
      advance();
      if (c == '"') break;
      if (c == '\\' && !eof() && (peek() == '"' || peek() == '\\')) {
        out += peek();
        advance();
        continue;
      }
      out += c;
    }
    return out;
  }
  void expect_semicolon(const char* section) {
    skip_space();
    if (peek() != ';') {
      fail(line_, std::string("expected ';' to end ") + section + ", found " + found());
    }
    advance();
  }

  // ---------------------------------------------------------------- sections
  void parse_nodes() {
    skip_inline_space();
    if (peek() == ':') ++pos_;
    while (!at_line_end()) {
      if (!is_ident_start(peek())) fail(line_, "expected a node name in BU_, found " + found());
      db_.nodes.push_back(identifier("a node name"));
    }
  }

  void parse_message(int line) {
    const auto raw_id = static_cast<std::uint32_t>(unsigned_integer("message id", 0xFFFFFFFFu));
    const std::string name = identifier("a message name after the BO_ id");
    expect(':', "after the message name");
    const auto length =
        static_cast<std::uint32_t>(unsigned_integer("message length", kMaxMessageBytes));
    skip_inline_space();
    std::string sender;
    if (!at_line_end()) {
      if (!is_ident_start(peek())) fail(line_, "expected the sender node of BO_, found " + found());
      sender = identifier("the sender node");
    }
    if (!at_line_end()) fail(line_, "unexpected " + found() + " after BO_ " + name);

    if (name == "VECTOR__INDEPENDENT_SIG_MSG") {
      // Vector's pseudo message for signals not placed in any frame: not a real frame.
      warn(line, "pseudo message VECTOR__INDEPENDENT_SIG_MSG and its signals skipped");
      current_message_ = kSkippedMessage;
      return;
    }
    const bool extended = (raw_id & kExtendedFlag) != 0;
    const std::uint32_t id = raw_id & ~kExtendedFlag;
    if (extended ? id > 0x1FFFFFFFu : id > 0x7FFu) {
      fail(line, "message id " + std::to_string(raw_id) + " of " + name + " is out of range for " +
                     (extended ? "a 29-bit" : "an 11-bit") + " identifier");
    }
    if (const auto it = by_dbc_id_.find(raw_id); it != by_dbc_id_.end()) {
      fail(line, "duplicate message id " + std::to_string(raw_id) + " (" + name + ", first " +
                     db_.messages[it->second].name + " at line " +
                     std::to_string(db_.messages[it->second].line) + ")");
    }
    if (const auto it = by_name_.find(name); it != by_name_.end()) {
      fail(line, "duplicate message name " + name + " (first at line " +
                     std::to_string(db_.messages[it->second].line) + ")");
    }
    MessageDef m;
    m.id = id;
    m.extended = extended;
    m.name = name;
    m.length_bytes = length;
    m.sender = sender;
    m.line = line;
    by_dbc_id_.emplace(raw_id, db_.messages.size());
    by_name_.emplace(name, db_.messages.size());
    current_message_ = db_.messages.size();
    db_.messages.push_back(std::move(m));
    explicit_cycle_.push_back(false);
    explicit_start_.emplace_back();
  }

  static std::uint32_t required_bytes(const SignalDef& s) {
    if (s.byte_order == ByteOrder::kIntel) return (s.start_bit + s.length_bits - 1) / 8 + 1;
    // Motorola: MSB at start_bit; bits available in the first byte = start_bit % 8 + 1.
    const std::uint32_t first = s.start_bit % 8 + 1;
    const std::uint32_t rest = s.length_bits > first ? s.length_bits - first : 0;
    return s.start_bit / 8 + 1 + (rest + 7) / 8;
  }

  void parse_signal(int line) {
    // Signals are read even for a skipped pseudo message, then dropped.
    if (current_message_ == kNoMessage) fail(line, "SG_ outside a BO_ block");
    SignalDef s;
    s.line = line;
    s.name = identifier("a signal name after SG_");
    skip_space();
    if (peek() != ':') {
      const std::string mux = identifier("a multiplexer indicator (M or mN) or ':'");
      if (mux == "M") {
        s.mux_role = MuxRole::kMultiplexor;
      } else if (mux.size() >= 2 && mux[0] == 'm' && mux[1] >= '0' && mux[1] <= '9') {
        std::size_t digits_end = 1;
        while (digits_end < mux.size() && mux[digits_end] >= '0' && mux[digits_end] <= '9') {
          ++digits_end;
        }
        if (digits_end != mux.size()) {
          fail(line, "multiplexer indicator '" + clip(mux) + "' of " + s.name +
                         " is not supported (extended multiplexing)");
        }
        std::uint32_t value = 0;
        const auto [end, ec] = std::from_chars(mux.data() + 1, mux.data() + mux.size(), value);
        if (ec != std::errc() || end != mux.data() + mux.size()) {
          fail(line, "bad multiplexer value '" + clip(mux) + "' of " + s.name);
        }
        s.mux_role = MuxRole::kMultiplexed;
        s.mux_value = value;
      } else {
        fail(line, "bad multiplexer indicator '" + clip(mux) + "' of " + s.name);
      }
    }
    expect(':', "after the signal name");
    s.start_bit =
        static_cast<std::uint32_t>(unsigned_integer("start bit", kMaxMessageBytes * 8 - 1));
    expect('|', "between start bit and length");
    s.length_bits = static_cast<std::uint32_t>(unsigned_integer("signal length", kMaxSignalBits));
    if (s.length_bits == 0) fail(line, "signal " + s.name + " has length 0");
    expect('@', "before the byte order");
    skip_space();
    if (peek() == '1') {
      s.byte_order = ByteOrder::kIntel;
    } else if (peek() == '0') {
      s.byte_order = ByteOrder::kMotorola;
    } else {
      fail(line_, "expected byte order 0 or 1 after '@', found " + found());
    }
    advance();
    if (peek() == '+') {
      s.is_signed = false;
    } else if (peek() == '-') {
      s.is_signed = true;
    } else {
      fail(line_, "expected '+' or '-' after the byte order, found " + found());
    }
    advance();
    expect('(', "before factor");
    s.factor = real("the factor");
    expect(',', "between factor and offset");
    s.offset = real("the offset");
    expect(')', "after the offset");
    expect('[', "before minimum");
    s.minimum = real("the minimum");
    expect('|', "between minimum and maximum");
    s.maximum = real("the maximum");
    expect(']', "after the maximum");
    s.unit = string_literal();
    while (!at_line_end()) {
      if (peek() == ',') {
        ++pos_;
        continue;
      }
      if (!is_ident_start(peek())) fail(line_, "expected a receiver node, found " + found());
      s.receivers.push_back(identifier("a receiver node"));
    }
    if (s.factor == 0.0) fail(line, "signal " + s.name + " has factor 0");
    if (current_message_ == kSkippedMessage) return;

    MessageDef& m = db_.messages[current_message_];
    if (required_bytes(s) > m.length_bytes) {
      fail(line, "signal " + s.name + " (start bit " + std::to_string(s.start_bit) + ", length " +
                     std::to_string(s.length_bits) + ", " +
                     (s.byte_order == ByteOrder::kIntel ? "Intel" : "Motorola") +
                     ") does not fit in message " + m.name + " of " +
                     std::to_string(m.length_bytes) + " bytes");
    }
    if (m.find_signal(s.name) != nullptr) {
      fail(line, "duplicate signal " + s.name + " in message " + m.name);
    }
    if (s.mux_role == MuxRole::kMultiplexor) {
      for (const auto& other : m.signals) {
        if (other.mux_role == MuxRole::kMultiplexor) {
          fail(line, "second multiplexor " + s.name + " in message " + m.name + " (first " +
                         other.name + ")");
        }
      }
    }
    m.signals.push_back(std::move(s));
    explicit_start_[current_message_].push_back(false);
  }

  /// Reads `id name` of a signal reference; returns {message, signal} or nullopt-like kNoMessage.
  std::pair<std::size_t, std::size_t> signal_ref(int line, const char* section, bool required) {
    const auto raw_id = static_cast<std::uint32_t>(unsigned_integer("message id", 0xFFFFFFFFu));
    const std::string name = identifier("a signal name");
    const auto it = by_dbc_id_.find(raw_id);
    if (it != by_dbc_id_.end()) {
      const auto& signals = db_.messages[it->second].signals;
      for (std::size_t i = 0; i < signals.size(); ++i) {
        if (signals[i].name == name) return {it->second, i};
      }
    }
    const std::string what = std::string(section) + " refers to unknown signal " + name +
                             " of message id " + std::to_string(raw_id);
    if (required) fail(line, what);
    warn(line, what + ", ignored");
    return {kNoMessage, 0};
  }
  std::size_t message_ref(int line, const char* section) {
    const auto raw_id = static_cast<std::uint32_t>(unsigned_integer("message id", 0xFFFFFFFFu));
    const auto it = by_dbc_id_.find(raw_id);
    if (it != by_dbc_id_.end()) return it->second;
    warn(line, std::string(section) + " refers to unknown message id " + std::to_string(raw_id) +
                   ", ignored");
    return kNoMessage;
  }

  void parse_comment(int line) {
    skip_space();
    if (peek() == '"') {
      (void)string_literal();  // network comment
      expect_semicolon("CM_");
      return;
    }
    const std::string target = identifier("BU_, BO_, SG_, EV_ or a string after CM_");
    if (target == "BO_") {
      const std::size_t m = message_ref(line, "CM_ BO_");
      std::string text = string_literal();
      if (m != kNoMessage) db_.messages[m].comment = std::move(text);
    } else if (target == "SG_") {
      const auto [m, s] = signal_ref(line, "CM_ SG_", false);
      std::string text = string_literal();
      if (m != kNoMessage) db_.messages[m].signals[s].comment = std::move(text);
    } else if (target == "BU_" || target == "EV_") {
      (void)identifier("a name");
      (void)string_literal();
    } else {
      fail(line, "unknown comment target '" + clip(target) + "' in CM_");
    }
    expect_semicolon("CM_");
  }

  void parse_attribute_definition() {
    AttributeDefinition def;
    skip_space();
    if (peek() != '"') def.object_type = identifier("BU_, BO_, SG_, EV_ or the attribute name");
    def.name = string_literal();
    def.value_type = identifier("the attribute value type");
    skip_statement();  // the type's parameters (ranges, enum strings) are not needed
    db_.attribute_definitions.push_back(std::move(def));
  }

  AttributeValue attribute_value() {
    skip_space();
    AttributeValue v;
    v.line = line_;
    if (peek() == '"') {
      v.text = string_literal();
      v.is_string = true;
    } else {
      const std::string_view token = number_token();
      if (token.empty()) fail(line_, "expected an attribute value, found " + found());
      v.text = std::string(token);
    }
    return v;
  }

  double attribute_number(const AttributeValue& v, const std::string& name) {
    std::string_view digits = v.text;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (v.is_string || ec != std::errc() || end != digits.data() + digits.size() ||
        !std::isfinite(value)) {
      fail(v.line, "bad value '" + clip(v.text) + "' for attribute " + name);
    }
    return value;
  }

  void parse_attribute_default(int line) {
    const std::string name = string_literal();
    const AttributeValue value = attribute_value();
    expect_semicolon("BA_DEF_DEF_");
    for (auto& def : db_.attribute_definitions) {
      if (def.name == name) {
        def.default_value = value.text;
        if (name == "GenMsgCycleTime") default_cycle_ = cycle_time(value);
        if (name == "GenSigStartValue") default_start_ = attribute_number(value, name);
        return;
      }
    }
    warn(line, "BA_DEF_DEF_ for undefined attribute " + clip(name) + ", ignored");
  }

  std::uint32_t cycle_time(const AttributeValue& v) {
    const double ms = attribute_number(v, "GenMsgCycleTime");
    if (ms < 0.0 || ms > kMaxCycleTimeMs || ms != std::floor(ms)) {
      fail(v.line, "GenMsgCycleTime " + clip(v.text) + " is not a whole number of ms in [0, " +
                       std::to_string(kMaxCycleTimeMs) + "]");
    }
    return static_cast<std::uint32_t>(ms);
  }

  void parse_attribute(int line) {
    const std::string name = string_literal();
    skip_space();
    std::size_t message = kNoMessage;
    std::size_t signal = 0;
    bool on_signal = false;
    if (peek() != '"' && is_ident_start(peek())) {
      const std::string target = identifier("BU_, BO_, SG_ or EV_");
      if (target == "BO_") {
        message = message_ref(line, "BA_ BO_");
      } else if (target == "SG_") {
        std::tie(message, signal) = signal_ref(line, "BA_ SG_", false);
        on_signal = true;
      } else if (target == "BU_" || target == "EV_") {
        (void)identifier("a name");
      } else {
        warn(line, "BA_ on '" + clip(target) + "' is not supported, skipped");
        skip_statement();
        return;
      }
    }
    const AttributeValue value = attribute_value();
    expect_semicolon("BA_");
    if (message == kNoMessage) return;
    if (name == "GenMsgCycleTime" && !on_signal) {
      db_.messages[message].cycle_time_ms = cycle_time(value);
      explicit_cycle_[message] = true;
    } else if (name == "VFrameFormat" && !on_signal) {
      // ENUM index or name: 14 StandardCAN_FD, 15 ExtendedCAN_FD (an FD frame of <= 8 bytes).
      db_.messages[message].fd_format =
          value.text == "14" || value.text == "15" || value.text.ends_with("CAN_FD");
    } else if (name == "GenSigStartValue" && on_signal) {
      db_.messages[message].signals[signal].start_value_raw = attribute_number(value, name);
      explicit_start_[message][signal] = true;
    }
  }

  void parse_value_descriptions(int line) {
    skip_space();
    if (!(peek() >= '0' && peek() <= '9')) {
      warn(line, "VAL_ for an environment variable skipped");
      skip_statement();
      return;
    }
    const auto [m, s] = signal_ref(line, "VAL_", false);
    std::vector<ValueDescription> values;
    while (true) {
      skip_space();
      if (eof()) fail(line, "VAL_ not terminated by ';'");
      if (peek() == ';') {
        advance();
        break;
      }
      ValueDescription d;
      d.value = signed_integer("a VAL_ value");
      d.text = string_literal();
      values.push_back(std::move(d));
    }
    if (m != kNoMessage) db_.messages[m].signals[s].value_descriptions = std::move(values);
  }

  void parse_value_type(int line) {
    const auto [m, s] = signal_ref(line, "SIG_VALTYPE_", true);
    expect(':', "in SIG_VALTYPE_");
    const auto type = unsigned_integer("SIG_VALTYPE_ type", 2);
    expect_semicolon("SIG_VALTYPE_");
    SignalDef& sig = db_.messages[m].signals[s];
    if (type == 1 && sig.length_bits != 32) {
      fail(line, "float signal " + sig.name + " must be 32 bits long, not " +
                     std::to_string(sig.length_bits));
    }
    if (type == 2 && sig.length_bits != 64) {
      fail(line, "double signal " + sig.name + " must be 64 bits long, not " +
                     std::to_string(sig.length_bits));
    }
    if (type != 0 && sig.mux_role == MuxRole::kMultiplexor) {
      fail(line, "multiplexor " + sig.name + " cannot be a float");
    }
    sig.value_type = type == 1   ? ValueType::kFloat32
                     : type == 2 ? ValueType::kFloat64
                                 : ValueType::kInteger;
  }

  void finish() {
    for (std::size_t mi = 0; mi < db_.messages.size(); ++mi) {
      MessageDef& m = db_.messages[mi];
      if (!explicit_cycle_[mi]) m.cycle_time_ms = default_cycle_;
      bool has_multiplexor = false;
      for (const auto& s : m.signals) has_multiplexor |= s.mux_role == MuxRole::kMultiplexor;
      for (std::size_t si = 0; si < m.signals.size(); ++si) {
        SignalDef& s = m.signals[si];
        if (!explicit_start_[mi][si]) s.start_value_raw = default_start_;
        if (s.mux_role == MuxRole::kMultiplexed && !has_multiplexor) {
          fail(s.line, "multiplexed signal " + s.name + " in message " + m.name +
                           " which has no multiplexor (M)");
        }
      }
    }
  }

  static constexpr std::size_t kSkippedMessage = kNoMessage - 1;

  std::string_view text_;
  std::string_view file_;
  std::size_t pos_ = 0;
  int line_ = 1;
  Database db_;
  std::size_t current_message_ = kNoMessage;
  std::unordered_map<std::uint32_t, std::size_t> by_dbc_id_;
  std::unordered_map<std::string, std::size_t> by_name_;
  std::vector<bool> explicit_cycle_;
  std::vector<std::vector<bool>> explicit_start_;
  std::uint32_t default_cycle_ = 0;
  double default_start_ = 0.0;
};

}  // namespace

Database parse_dbc(std::string_view text, std::string_view file_name) {
  Database db = Parser(text, file_name).run();
  check_semantics(db);
  return db;
}

Database load_dbc(const std::filesystem::path& file) {
  return parse_dbc(config::read_input_file(file), file.string());
}

}  // namespace rig::io::can::dbc
