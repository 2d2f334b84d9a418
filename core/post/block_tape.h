// The tape as blocks: the last link of every G-code sink chain (milling,
// lathe, probing). It numbers the blocks where the dialect numbers them
// (N words from sequenceStart by sequenceIncrement, wrapping past
// sequenceMax), keeps every line within the dialect's maxLineLength,
// writes comments in the dialect's form, and records where each line came
// from. The writers before it decide the words; none of them counts blocks
// or measures lines itself.
#pragma once

#include "post/dialect.h"
#include "post/post.h"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace taiwa::post {

class BlockTape {
public:
    explicit BlockTape(const Dialect& dialect) : dialect_(dialect) {}

    // Where the following lines come from.
    void source(BlockSource where) { source_ = where; }

    // An unnumbered line: '%', the O-number line, a label the program jumps to.
    void line(std::string_view text);
    // A comment in the dialect's form ("(…)" or "; …"), its text made safe
    // for the control (commentText) and cut to the line limit.
    void comment(const std::string& text);
    // A whole block: numbered when the dialect numbers blocks, refused
    // (std::length_error) when longer than the line limit.
    void block(std::string_view words);

    // A block written word by word: begun (its N word), words appended
    // (separated by a space from the one before), ended (length checked,
    // line and source recorded).
    void beginBlock();
    void word(std::string_view w);
    void word(char letter, std::string_view number);
    void append(std::string_view raw);  // as it is, no separator
    void endBlock();

    // A place in the tape to go back to when a begun block turns out to say
    // nothing (a move to where the tool already is): no line, no number.
    struct Mark {
        std::size_t size = 0;
        int sequence = 0;
    };
    Mark mark() const { return {text_.size(), sequence_}; }
    void rollback(Mark m);

    // The N number the k-th block from now gets (k = 1: the next): FANUC's
    // G71 P and Q name blocks not yet written.
    int sequenceAhead(int k) const;

    void reserve(std::size_t blocks)
    {
        text_.reserve(blocks * 30);
        sources_.reserve(blocks);
    }
    const std::string& text() const { return text_; }
    const std::vector<BlockSource>& sources() const { return sources_; }
    std::string takeText() { return std::move(text_); }
    std::vector<BlockSource> takeSources() { return std::move(sources_); }

private:
    const Dialect& dialect_;
    int sequence_ = 0;
    std::size_t blockStart_ = 0, wordsStart_ = 0;  // of the block being written, in text_
    BlockSource source_;
    std::string text_;
    std::vector<BlockSource> sources_;
};

}  // namespace taiwa::post
