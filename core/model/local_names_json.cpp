// The data files' "names" maps (local_names_json.h): checked when read.
#include "model/local_names_json.h"

#include <regex>

namespace taiwa {

Result<LocalNames> localNamesFrom(const nlohmann::json& value)
{
    if (!value.is_object()) return Failure{"must be an object of language codes to names, as {\"ja\": \"…\", \"zh\": \"…\"}"};
    static const std::regex code("[a-z]{2,3}(-[A-Za-z0-9]{2,8})?");
    LocalNames names;
    for (const auto& [language, text] : value.items()) {
        if (!std::regex_match(language, code))
            return Failure{"'" + language + "' is not a language code (\"ja\", \"zh\", \"zh-TW\")"};
        if (!text.is_string() || text.get<std::string>().find_first_not_of(" \t") == std::string::npos)
            return Failure{"the name in '" + language + "' must be a text that is not empty"};
        names[language] = text.get<std::string>();
    }
    return names;
}

nlohmann::json localNamesJson(const LocalNames& names)
{
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [language, text] : names) out[language] = text;
    return out;
}

}  // namespace taiwa
