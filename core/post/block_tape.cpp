// Block numbers, line limits and comments of every G-code tape (see
// block_tape.h).
#include "post/block_tape.h"

#include "post/gcode_writer.h"

#include <fmt/format.h>

#include <charconv>
#include <stdexcept>

namespace taiwa::post {

void BlockTape::line(std::string_view text)
{
    text_ += text;
    text_ += '\n';
    sources_.push_back(source_);
}

void BlockTape::comment(const std::string& text)
{
    if (dialect_.semicolonComments) {
        std::string c = "; " + commentText(text, dialect_.upperCaseComments);
        if (c.size() > dialect_.maxLineLength) c.resize(dialect_.maxLineLength);
        line(c);
        return;
    }
    std::string c = "(" + commentText(text, dialect_.upperCaseComments);
    if (c.size() + 1 > dialect_.maxLineLength) c.resize(dialect_.maxLineLength - 1);
    c += ')';
    line(c);
}

int BlockTape::sequenceAhead(int k) const
{
    int s = sequence_;
    for (int i = 0; i < k; ++i)
        s = s == 0 || s + dialect_.sequenceIncrement > dialect_.sequenceMax ? dialect_.sequenceStart : s + dialect_.sequenceIncrement;
    return s;
}

void BlockTape::beginBlock()
{
    blockStart_ = text_.size();
    if (dialect_.sequenceNumbers) {
        sequence_ = sequenceAhead(1);
        char n[16];
        const auto [end, ec] = std::to_chars(n, n + sizeof n, sequence_);
        text_ += 'N';
        text_.append(n, end);
        text_ += ' ';
    }
    wordsStart_ = text_.size();
}

void BlockTape::word(std::string_view w)
{
    if (w.empty()) return;
    if (text_.size() > wordsStart_) text_ += ' ';
    text_ += w;
}

void BlockTape::word(char letter, std::string_view number)
{
    if (text_.size() > wordsStart_) text_ += ' ';
    text_ += letter;
    text_ += number;
}

void BlockTape::append(std::string_view raw) { text_ += raw; }

void BlockTape::endBlock()
{
    if (text_.size() - blockStart_ > dialect_.maxLineLength)
        throw std::length_error(fmt::format("post-processor: block longer than {} characters: {}", dialect_.maxLineLength,
                                            text_.substr(blockStart_)));
    text_ += '\n';
    sources_.push_back(source_);
}

void BlockTape::block(std::string_view words)
{
    beginBlock();
    text_ += words;
    endBlock();
}

void BlockTape::rollback(Mark m)
{
    text_.resize(m.size);
    sequence_ = m.sequence;
}

}  // namespace taiwa::post
