// The dialect table: FANUC 0i style and LinuxCNC RS274/NGC.
#include "post/dialect.h"

#include "post/post.h"

namespace taiwa::post {

const std::vector<Dialect>& dialects()
{
    static const std::vector<Dialect> table{
        {
            .name = "fanuc",
            .percentFraming = true,
            .programNumber = true,
            .sequenceNumbers = true,
            .sequenceIncrement = 10,
            .decimalPointAlways = true,
            .upperCaseComments = true,
            .preamble = {"G17 {UNITS} G40 G49 G80 G90"},
            .retract = {"G91 G28 Z0.", "G90"},
            .lengthOffsetWithFirstZ = true,
            .cycleRetractMode = "G98",
        },
        {
            .name = "linuxcnc",
            .percentFraming = false,
            .programNumber = false,
            .sequenceNumbers = false,
            .sequenceIncrement = 10,
            .decimalPointAlways = false,
            .upperCaseComments = false,
            .preamble = {"G17 {UNITS} G40 G49 G80 G90 G94 G64 P0.01"},
            .retract = {"G53 G0 Z0"},
            .lengthOffsetWithFirstZ = false,
            .cycleRetractMode = "G98",
        },
    };
    return table;
}

const Dialect* findDialect(const std::string& name)
{
    for (const auto& d : dialects())
        if (d.name == name) return &d;
    return nullptr;
}

}  // namespace taiwa::post

namespace taiwa {

std::vector<std::string> dialectNames()
{
    std::vector<std::string> names;
    for (const auto& d : post::dialects()) names.push_back(d.name);
    return names;
}

bool isDialect(const std::string& name) { return post::findDialect(name) != nullptr; }

}  // namespace taiwa
