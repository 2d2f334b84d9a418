// The names the elements written from contours get (figure_from_contours.h):
// P1, L1, C1, K1... numbered on through all contours, each name already in
// the figure skipped, with the caller's prefix; a contour's attempts take
// their names back or give them again. Internal to core/figure/.
#pragma once

#include "figure/figure_from_contours.h"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_set>
#include <vector>

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
        for (;;) {
            std::string name = prefix_ + kind + std::to_string(++count_[kind]);
            if (taken_.insert(name).second) {
                added_.push_back(name);
                return name;
            }
        }
    }

    // The names given since the last mark, to be taken back or given again:
    // a contour is written up to four times (more decimals each time) and
    // only one of its attempts keeps its names. Taking back costs what the
    // attempt added, never a copy of every name so far (which made many
    // contours quadratic).
    struct Given {
        std::vector<std::string> names;
        std::map<char, int> count;
    };
    void mark() { added_.clear(), countAtMark_ = count_; }
    // Room for `more` names at once (a contour of many segments): the set
    // grows at least twofold, never by each contour's few (a rehash of all
    // names so far per contour).
    void reserve(std::size_t more)
    {
        const std::size_t need = taken_.size() + more;
        if (static_cast<double>(need) > static_cast<double>(taken_.bucket_count()) * taken_.max_load_factor())
            taken_.reserve(std::max(need, 2 * taken_.size()));
        added_.reserve(more);
    }
    Given takeBack()
    {
        Given g{std::move(added_), count_};
        for (const auto& name : g.names) taken_.erase(name);
        added_.clear();
        count_ = countAtMark_;
        return g;
    }
    void giveAgain(const Given& g)
    {
        for (const auto& name : g.names) taken_.insert(name);
        count_ = g.count;
    }

private:
    std::string prefix_;
    std::unordered_set<std::string> taken_;
    std::vector<std::string> added_;
    std::map<char, int> count_, countAtMark_;
};

}  // namespace taiwa::figure
