// Units: one table of named units and a small recursive-descent parser.
//
//   product := power (('*' | '·' | '⋅' | '/') power)*      left to right
//   power   := primary ('^' ['-' | '+'] digits | superscript)*
//   primary := name | '1' | '(' product ')'
#include "core/model/units.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

namespace drape {
namespace {

constexpr double kGravity = 9.80665;               // standard gravity [m/s²]
constexpr double kPound = 0.45359237;              // avoirdupois pound [kg]
constexpr double kOunce = 0.028349523125;          // avoirdupois ounce = pound / 16 [kg]
constexpr double kInch = 0.0254;                   // [m]
constexpr double kGramForce = 1e-3 * kGravity;     // [N]
constexpr double kOunceForce = kOunce * kGravity;  // [N]
constexpr double kPoundForce = kPound * kGravity;  // [N]
constexpr Dimension kTime{0, 0, 1, 0};
constexpr int kMaxExponent = 99;  // keeps the integer exponents far from overflow
// Each '(' is a level of recursion: without a bound, a long enough run of
// them overflowed the stack.
constexpr int kMaxNesting = 32;

struct NamedUnit {
  std::string_view name;
  double si_factor;
  Dimension dimension;
};

// `oz` and `lb` are forces, as in the textile literature.
constexpr NamedUnit kUnits[] = {
    {"m", 1.0, dim::kLength},
    {"cm", 1e-2, dim::kLength},
    {"mm", 1e-3, dim::kLength},
    {"um", 1e-6, dim::kLength},
    {"in", kInch, dim::kLength},
    {"ft", 12 * kInch, dim::kLength},
    {"N", 1.0, dim::kForce},
    {"kN", 1e3, dim::kForce},
    {"mN", 1e-3, dim::kForce},
    {"gf", kGramForce, dim::kForce},
    {"gmf", kGramForce, dim::kForce},
    {"kgf", kGravity, dim::kForce},
    {"ozf", kOunceForce, dim::kForce},
    {"oz", kOunceForce, dim::kForce},
    {"lbf", kPoundForce, dim::kForce},
    {"lb", kPoundForce, dim::kForce},
    {"kg", 1.0, dim::kMass},
    {"g", 1e-3, dim::kMass},
    {"Pa", 1.0, dim::kPressure},
    {"kPa", 1e3, dim::kPressure},
    {"MPa", 1e6, dim::kPressure},
    {"GPa", 1e9, dim::kPressure},
    {"psi", kPoundForce / (kInch * kInch), dim::kPressure},
    {"deg", std::numbers::pi / 180, dim::kAngle},
    {"rad", 1.0, dim::kAngle},
    {"s", 1.0, kTime},
};

struct NamedDimension {
  Dimension dimension;
  std::string_view name;
  std::string_view examples;
};

// kMomentPerWidth == kForce and kBendingRigidity == kMoment, so they share names.
constexpr NamedDimension kDimensionNames[] = {
    {dim::kNone, "dimensionless", ""},
    {dim::kLength, "length", "m, cm, mm, in, ft"},
    {dim::kMass, "mass", "kg, g"},
    {dim::kAngle, "angle", "deg, rad"},
    {dim::kForce, "force", "N, gf, oz, lbf"},
    {dim::kArea, "area", "m^2, cm^2, in^2"},
    {dim::kPressure, "force/area", "Pa, kPa, MPa, GPa, psi, gf/cm^2, oz/in^2"},
    {dim::kArealDensity, "mass/area", "kg/m^2, g/m^2, g/cm^2"},
    {dim::kCurvature, "curvature", "1/m, 1/cm, 1/in"},
    {dim::kMoment, "force·length", "N*m, gf*cm^2/cm"},
    {dim::kForcePerLength, "force/length", "N/m, gf/cm, lbf/in"},
    {dim::kPenaltyPerArea, "force/length^3", "N/m^3, gf/cm^3"},
};

const NamedDimension* FindDimension(Dimension d) {
  for (const NamedDimension& named : kDimensionNames) {
    if (named.dimension == d) return &named;
  }
  return nullptr;
}

// "m^-1 kg s^-2 rad^1": exponents of the SI base units, zero ones left out.
std::string SpelledOut(Dimension d) {
  const std::pair<const char*, int> parts[] = {
      {"m", d.length}, {"kg", d.mass}, {"s", d.time}, {"rad", d.angle}};
  std::string text;
  for (const auto& [symbol, exponent] : parts) {
    if (exponent == 0) continue;
    if (!text.empty()) text += ' ';
    text += std::string(symbol) + '^' + std::to_string(exponent);
  }
  return text;
}

// "a length", "an area", "dimensionless", "of dimension m^1 s^-1": fits after "is".
std::string Found(Dimension d) {
  const NamedDimension* named = FindDimension(d);
  if (named == nullptr) return "of dimension " + SpelledOut(d);
  if (d == dim::kNone) return "dimensionless";
  const bool vowel = std::string_view("aeiou").find(named->name[0]) != std::string_view::npos;
  return std::string(vowel ? "an " : "a ") + std::string(named->name);
}

// "a length (m, cm, mm, in, ft)": fits after "expected".
std::string Expected(Dimension d) {
  if (d == dim::kNone) return "a dimensionless number";
  const NamedDimension* named = FindDimension(d);
  if (named == nullptr) return "dimension " + SpelledOut(d);
  return Found(d) + " (" + std::string(named->examples) + ")";
}

std::string KnownUnits() {
  std::string text;
  for (const NamedUnit& unit : kUnits) {
    if (!text.empty()) text += ", ";
    text += unit.name;
  }
  return text;
}

// Built by appending: GCC 12 -O3 warns falsely (-Wrestrict) on "'" + std::string(...).
std::string Enclosed(std::string_view text, char quote) {
  std::string result(1, quote);
  result += text;
  result += quote;
  return result;
}

// The user's whole text is quoted "so", a part of it 'so'.
std::string Quoted(std::string_view text) {
  return Enclosed(text, '"');
}
std::string SingleQuoted(std::string_view text) {
  return Enclosed(text, '\'');
}

std::string_view Trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r\n");
  return text.substr(first, last - first + 1);
}

bool IsAsciiLetter(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
}
bool IsDigit(char c) {
  return c >= '0' && c <= '9';
}

// Unicode superscript digits and minus, as UTF-8.
constexpr std::string_view kSuperscripts[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
constexpr std::string_view kSuperscriptMinus = "⁻";

// A superscript integer ("²", "⁻¹") at the start of `rest`: its length in
// bytes (0 if there is none) and its value.
std::pair<std::size_t, int> LeadingSuperscript(std::string_view rest) {
  const std::size_t sign = rest.starts_with(kSuperscriptMinus) ? kSuperscriptMinus.size() : 0;
  std::size_t size = sign;
  int value = 0;
  while (value <= kMaxExponent) {
    const auto digit = std::ranges::find_if(kSuperscripts, [&](std::string_view glyph) {
      return rest.substr(size).starts_with(glyph);
    });
    if (digit == std::end(kSuperscripts)) break;
    value = 10 * value + static_cast<int>(digit - std::begin(kSuperscripts));
    size += digit->size();
  }
  if (size == sign) return {0, 0};
  return {size, sign > 0 ? -value : value};
}

enum class TokenKind {
  kName,
  kNumber,
  kTimes,
  kDivide,
  kCaret,
  kSign,
  kOpen,
  kClose,
  kSuper,
  kEnd,
  kOther
};

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string_view text;
  int value = 0;  // exponent of a kSuper token
};

class UnitParser {
 public:
  // `context` is the whole text the expression came from, quoted in messages.
  UnitParser(std::string_view expression, std::string_view context)
      : text_(expression), context_(context) {}

  Unit Parse() {
    if (Peek().kind == TokenKind::kEnd) Fail("expected a unit");
    const Unit unit = Product();
    ExpectOperatorOrEnd(false);
    if (!std::isfinite(unit.si_factor) || unit.si_factor == 0.0) {
      Fail("unit " + SingleQuoted(text_) +
           " is out of range (its factor to SI units must lie between about 1e-308 and 1e308)");
    }
    return unit;
  }

 private:
  Unit Product() {
    Unit unit = Power();
    for (;;) {
      const TokenKind kind = Peek().kind;
      if (kind != TokenKind::kTimes && kind != TokenKind::kDivide) return unit;
      Take();
      const Unit right = Power();
      if (kind == TokenKind::kTimes) {
        unit = {unit.si_factor * right.si_factor, unit.dimension * right.dimension};
      } else {
        unit = {unit.si_factor / right.si_factor, unit.dimension / right.dimension};
      }
      // Bounded here as after '^': repeated factors would otherwise add up
      // past the range of int.
      CheckExponents(unit.dimension);
    }
  }

  void CheckExponents(const Dimension& e) const {
    if (std::abs(e.length) > kMaxExponent || std::abs(e.mass) > kMaxExponent ||
        std::abs(e.time) > kMaxExponent || std::abs(e.angle) > kMaxExponent) {
      Fail("exponent too large: " + SpelledOut(e) + " (at most " + std::to_string(kMaxExponent) +
           ")");
    }
  }

  Unit Power() {
    Unit unit = Primary();
    for (;;) {
      int exponent = 0;
      if (Peek().kind == TokenKind::kSuper) {
        exponent = Take().value;
      } else if (Peek().kind == TokenKind::kCaret) {
        Take();
        exponent = Exponent();
      } else {
        return unit;
      }
      const Dimension d = unit.dimension;
      unit.dimension = {
          d.length * exponent, d.mass * exponent, d.time * exponent, d.angle * exponent};
      unit.si_factor = std::pow(unit.si_factor, exponent);
      CheckExponents(unit.dimension);
    }
  }

  int Exponent() {
    bool negative = false;
    if (Peek().kind == TokenKind::kSign) negative = Take().text == "-";
    const Token digits = Peek();
    int value = 0;
    const auto [end, error] =
        std::from_chars(digits.text.data(), digits.text.data() + digits.text.size(), value);
    if (digits.kind != TokenKind::kNumber || end != digits.text.data() + digits.text.size()) {
      Fail("expected an integer exponent after '^', found " + Describe(digits));
    }
    if (error != std::errc() || value > kMaxExponent) {
      Fail("exponent " + SingleQuoted(digits.text) + " is too large (at most " +
           std::to_string(kMaxExponent) + ")");
    }
    Take();
    return negative ? -value : value;
  }

  Unit Primary() {
    const Token token = Take();
    switch (token.kind) {
      case TokenKind::kName:
        for (const NamedUnit& unit : kUnits) {
          if (unit.name == token.text) return {unit.si_factor, unit.dimension};
        }
        Fail("unknown unit " + SingleQuoted(token.text) + " (known: " + KnownUnits() + ")");
      case TokenKind::kNumber:
        if (token.text != "1") {
          Fail("unexpected number " + SingleQuoted(token.text) +
               " in a unit (only 1 may stand for a unit, as in '1/cm')");
        }
        return {1.0, dim::kNone};
      case TokenKind::kOpen: {
        if (++depth_ > kMaxNesting) {
          Fail("parentheses nested more than " + std::to_string(kMaxNesting) +
               " deep, at character " + std::to_string(pos_) + " of the unit");
        }
        const Unit inner = Product();
        if (Peek().kind != TokenKind::kClose) {
          if (Peek().kind == TokenKind::kEnd) Fail("missing ')'");
          ExpectOperatorOrEnd(true);
        }
        Take();
        --depth_;
        return inner;
      }
      default:
        Fail("expected a unit, found " + Describe(token));
    }
  }

  // After a complete factor: anything but an operator (or, `in_parentheses`,
  // a ')') is an error.
  void ExpectOperatorOrEnd(bool in_parentheses) {
    const Token token = Peek();
    switch (token.kind) {
      case TokenKind::kEnd:
        return;
      case TokenKind::kName:
      case TokenKind::kNumber:
      case TokenKind::kOpen:
        Fail("expected '*' or '/' before " + SingleQuoted(token.text));
      default:
        Fail("unexpected " + Describe(token) + " (expected '*', '/', '^' or " +
             (in_parentheses ? "')'" : "the end") + ")");
    }
  }

  static std::string Describe(const Token& token) {
    if (token.kind == TokenKind::kEnd) return "end of text";
    return SingleQuoted(token.text);
  }

  [[noreturn]] void Fail(const std::string& what) const {
    throw UnitError(what + " in " + Quoted(context_));
  }

  const Token& Peek() {
    if (!peeked_) {
      next_ = Lex();
      peeked_ = true;
    }
    return next_;
  }

  Token Take() {
    Peek();
    peeked_ = false;
    return next_;
  }

  Token Lex() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    const std::string_view rest = text_.substr(pos_);
    if (rest.empty()) return {TokenKind::kEnd, rest};
    const auto token = [&](TokenKind kind, std::size_t size, int value = 0) {
      pos_ += size;
      return Token{kind, rest.substr(0, size), value};
    };
    const auto run = [&](auto predicate) {
      std::size_t size = 0;
      while (size < rest.size() && predicate(rest[size])) ++size;
      return size;
    };
    const char c = rest[0];
    if (IsAsciiLetter(c)) return token(TokenKind::kName, run(IsAsciiLetter));
    if (IsDigit(c) || c == '.') {
      return token(TokenKind::kNumber, run([](char d) { return IsDigit(d) || d == '.'; }));
    }
    switch (c) {
      case '*':
        return token(TokenKind::kTimes, 1);
      case '/':
        return token(TokenKind::kDivide, 1);
      case '^':
        return token(TokenKind::kCaret, 1);
      case '-':
      case '+':
        return token(TokenKind::kSign, 1);
      case '(':
        return token(TokenKind::kOpen, 1);
      case ')':
        return token(TokenKind::kClose, 1);
    }
    for (const std::string_view dot : {"·", "⋅"}) {
      if (rest.starts_with(dot)) return token(TokenKind::kTimes, dot.size());
    }
    if (const auto [size, value] = LeadingSuperscript(rest); size > 0) {
      return token(TokenKind::kSuper, size, value);
    }
    // One UTF-8 code point: the lead byte and its continuation bytes.
    std::size_t size = 1;
    while (size < rest.size() && (static_cast<unsigned char>(rest[size]) & 0xC0) == 0x80) ++size;
    return token(TokenKind::kOther, size);
  }

  std::string_view text_;
  std::string_view context_;
  std::size_t pos_ = 0;
  int depth_ = 0;  // of parentheses open
  Token next_;
  bool peeked_ = false;
};

}  // namespace

std::string DimensionName(Dimension d) {
  const NamedDimension* named = FindDimension(d);
  if (named == nullptr) return SpelledOut(d);
  if (named->examples.empty()) return std::string(named->name);
  return std::string(named->name) + " (" + std::string(named->examples) + ")";
}

Unit ParseUnit(std::string_view expression) {
  return UnitParser(Trimmed(expression), expression).Parse();
}

Quantity ParseQuantity(std::string_view text) {
  const std::string_view trimmed = Trimmed(text);
  if (trimmed.empty()) {
    throw UnitError("empty quantity, expected a number and a unit such as \"0.489 mm\"");
  }
  // The number runs up to the first character that cannot be part of one.
  const std::string_view number = trimmed.substr(0, trimmed.find_first_not_of("0123456789.eE+-"));
  if (number.empty() ||
      !(IsDigit(number[0]) || number[0] == '.' || number[0] == '+' || number[0] == '-')) {
    throw UnitError("expected a number at the start of " + Quoted(text) + ", e.g. \"0.489 mm\"");
  }
  // from_chars takes no '+'; a '+' may not be followed by another sign.
  std::string_view digits = number;
  if (digits.starts_with('+')) digits.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  const bool signed_twice = digits.size() < number.size() && digits.starts_with('-');
  if (error == std::errc::result_out_of_range) {
    throw UnitError("number " + SingleQuoted(number) +
                    " is out of range (its size must lie between about 1e-308 and 1e308) in " +
                    Quoted(text));
  }
  if (error != std::errc() || end != digits.data() + digits.size() || signed_twice) {
    throw UnitError("malformed number " + SingleQuoted(number) +
                    " (expected a number such as 0.5 or 2e-3) in " + Quoted(text));
  }

  const std::string_view unit_text = Trimmed(trimmed.substr(number.size()));
  const Unit unit = unit_text.empty() ? Unit{1.0, dim::kNone} : UnitParser(unit_text, text).Parse();
  const Quantity quantity{value * unit.si_factor, unit.dimension};
  if (!std::isfinite(quantity.value_si)) {
    throw UnitError(Quoted(text) + " is out of range in SI units (at most about 1.8e308)");
  }
  return quantity;
}

double ParseQuantityAs(std::string_view text, Dimension expected) {
  const Quantity quantity = ParseQuantity(text);
  if (quantity.dimension != expected) {
    throw UnitError(Quoted(text) + " is " + Found(quantity.dimension) + ", expected " +
                    Expected(expected));
  }
  return quantity.value_si;
}

}  // namespace drape
