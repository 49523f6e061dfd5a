#pragma once
// Whitespace-separated tokens of a text grid file, with numbers parsed strictly (the whole token,
// std::from_chars) and the line of each token known for error messages. What the ASCII readers
// of src/grid/ share. Internal to src/grid/.

#include <charconv>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace vissort::detail {

/// text with its ASCII capitals in lower case: for keywords that the formats match in any case
/// (legacy VTK, Medit).
inline std::string lowerCase(std::string_view text) {
    std::string lower(text);
    for (char& c : lower)
        if (c >= 'A' && c <= 'Z')
            c = char(c - 'A' + 'a');
    return lower;
}

/// The token without a leading '+' that a sign does not follow: from_chars reads no '+', and "+-5"
/// must stay a bad number rather than become -5.
inline std::string_view withoutPlusSign(std::string_view token) {
    if (token.size() >= 2 && token[0] == '+' && token[1] != '-' && token[1] != '+')
        token.remove_prefix(1);
    return token;
}

class TokenScanner {
public:
    /// comment: a character that starts a comment running to the end of its line ('#' for
    /// tetgen and Medit), or '\0' for none.
    explicit TokenScanner(std::string_view text, char comment = '\0')
        : text_(text), comment_(comment) {}

    /// The next token, empty at the end of the text.
    std::string_view next() {
        skipSpaceAndComments();
        token_line_ = line_;
        const std::size_t start = pos_;
        while (pos_ < text_.size() && !isSpace(text_[pos_]) && text_[pos_] != comment_char())
            ++pos_;
        return text_.substr(start, pos_ - start);
    }

    /// The next token without consuming it.
    std::string_view peek() {
        const std::size_t pos = pos_, line = line_, token_line = token_line_;
        const std::string_view token = next();
        pos_ = pos;
        line_ = line;
        token_line_ = token_line;
        return token;
    }

    bool atEnd() {
        skipSpaceAndComments();
        return pos_ >= text_.size();
    }

    /// The rest of the current line (after the last token read), without its end of line: for
    /// line-based headers. Moves to the next line.
    std::string_view restOfLine() {
        const std::size_t start = pos_;
        while (pos_ < text_.size() && text_[pos_] != '\n')
            ++pos_;
        std::string_view rest = text_.substr(start, pos_ - start);
        if (pos_ < text_.size()) {
            ++pos_;
            ++line_;
        }
        if (!rest.empty() && rest.back() == '\r')
            rest.remove_suffix(1);
        return rest;
    }

    /// Where the next unread byte is: for binary sections that follow a text header.
    std::size_t position() const { return pos_; }
    void seek(std::size_t pos) { pos_ = pos; }

    /// The 1-based line of the last token returned by next().
    std::size_t line() const { return token_line_; }

    /// The next token as an integer or a finite double; nullopt when it is missing, not a number
    /// as a whole, out of range, or (for doubles) not finite.
    std::optional<int64_t> nextInteger() { return parseInteger(next()); }
    std::optional<double> nextDouble() { return parseDouble(next()); }

    static std::optional<int64_t> parseInteger(std::string_view token) {
        token = withoutPlusSign(token);
        int64_t value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (token.empty() || error != std::errc() || end != token.data() + token.size())
            return std::nullopt;
        return value;
    }
    static std::optional<double> parseDouble(std::string_view token) {
        token = withoutPlusSign(token);
        double value = 0;
        const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), value);
        if (token.empty() || error != std::errc() || end != token.data() + token.size() ||
            !(value - value == 0))
            return std::nullopt;
        return value;
    }

    /// How many more tokens the rest of the text can hold at most: each needs a character and a
    /// separator. Readers bound declared counts with it before reserving memory.
    uint64_t maxTokensLeft() const { return (text_.size() - pos_) / 2 + 1; }

private:
    static bool isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
    }
    char comment_char() const { return comment_ == '\0' ? ' ' : comment_; }
    void skipSpaceAndComments() {
        while (pos_ < text_.size()) {
            const char c = text_[pos_];
            if (c == '\n') {
                ++line_;
                ++pos_;
            } else if (isSpace(c)) {
                ++pos_;
            } else if (comment_ != '\0' && c == comment_) {
                while (pos_ < text_.size() && text_[pos_] != '\n')
                    ++pos_;
            } else {
                break;
            }
        }
    }

    std::string_view text_;
    char comment_;
    std::size_t pos_ = 0;
    std::size_t line_ = 1;
    std::size_t token_line_ = 1;
};

} // namespace vissort::detail
