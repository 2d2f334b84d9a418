// The names the elements written from contours get (figure_from_contours.h):
// P1, L1, C1, K1... numbered on through all contours, each name already in
// the figure skipped, with the caller's prefix; a contour's attempts take
// their names back or give them again. Internal to core/figure/.
#pragma once

#include "figure/figure_from_contours.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <unordered_set>

namespace taiwa::figure {

// A name's letters as the figure language reads them: upper case.
inline char upper(char c) { return (c >= 'a' && c <= 'z') ? static_cast<char>(c - 'a' + 'A') : c; }
inline bool isLetter(char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); }
inline bool isDigit(char c) { return c >= '0' && c <= '9'; }
inline std::string upper(std::string s)
{
    for (char& c : s) c = upper(c);
    return s;
}


// The names are the prefix, the kind's letter and a number counted per kind,
// so two names it gives never clash, and a name counted back is the same
// name when it is given again: only the figure's own names (FigureNaming::
// taken) are held, to be skipped. (Holding every name given as well cost a
// set of 600,000 strings for a drawn circle of 200,000 lines, filled and
// emptied again by each attempt.)
class Namer {
public:
    explicit Namer(const FigureNaming& n) : prefix_(upper(n.prefix))
    {
        const bool ok = prefix_.empty() ||
                        (isLetter(prefix_[0]) && std::all_of(prefix_.begin(), prefix_.end(), [](char c) {
                             return isLetter(c) || isDigit(c);
                         }));
        if (!ok) throw std::logic_error("figure names: the prefix '" + n.prefix + "' is not letters and digits");
        for (const auto& t : n.taken) taken_.insert(upper(t));
    }
    std::string next(char kind)
    {
        int& count = count_.at(static_cast<unsigned char>(kind));
        for (;;) {
            std::string name = prefix_ + kind + std::to_string(++count);
            if (taken_.empty() || taken_.count(name) == 0) return name;
        }
    }

    // The names given since the last mark, to be taken back or given again:
    // a contour is written up to four times (more decimals each time) and
    // only one of its attempts keeps its names. The counts say them all.
    struct Given {
        std::array<int, 128> count{};
    };
    void mark() { countAtMark_ = count_; }
    Given takeBack()
    {
        Given g{count_};
        count_ = countAtMark_;
        return g;
    }
    void giveAgain(const Given& g) { count_ = g.count; }

private:
    std::string prefix_;
    std::unordered_set<std::string> taken_;  // the figure's own names
    std::array<int, 128> count_{}, countAtMark_{};
};

}  // namespace taiwa::figure
