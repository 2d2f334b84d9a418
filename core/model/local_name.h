// A name the shop's data gives in other languages beside its own text (the
// default, English in the shipped files): a material's description, a
// machine's name, a tool's name, as a .desktop file's Name[ja]. The job,
// the tape, the sheet and the command line keep the default text; the
// station shows the one of its language (docs/station.md, "Languages").
#pragma once

#include <map>
#include <string>

namespace taiwa {

// Language code ("ja", "zh") to the name in that language.
using LocalNames = std::map<std::string, std::string>;

// The name in `language`; `text` (the default) when there is none.
inline const std::string& nameIn(const LocalNames& names, const std::string& language, const std::string& text)
{
    const auto it = names.find(language);
    return it == names.end() ? text : it->second;
}

}  // namespace taiwa
