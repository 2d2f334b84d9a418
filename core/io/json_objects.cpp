// Nested objects of a job document's object (io/json_objects.h).
#include "io/json_objects.h"

#include "io/job_messages.h"
#include "model/translate_noop.h"

#include <fmt/format.h>

#include <string>

namespace taiwa::io {

std::optional<ObjectFields> objectAt(const ObjectFields& f, const char* key, const char* what)
{
    const nlohmann::json* v = f.find(key);
    if (!v) return std::nullopt;
    if (!v->is_object()) {
        f.error(key, msg::io::wrongType(what ? what : TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object"), *v));
        return std::nullopt;
    }
    return f.nested(*v, std::string(key) + ".");
}

void eachObject(const ObjectFields& f, const char* key, const char* what, bool required,
                const std::function<void(const ObjectFields& item, std::size_t index)>& each)
{
    const nlohmann::json* list = f.find(key);
    if (!list || !list->is_array()) {
        if (list) f.error(key, msg::io::wrongType(what, *list));
        else if (required) f.error(key, msg::io::missing(what));
        return;
    }
    for (std::size_t i = 0; i < list->size(); ++i) {
        const std::string prefix = fmt::format("{}[{}].", key, i + 1);
        if (!(*list)[i].is_object()) {
            f.error(prefix.substr(0, prefix.size() - 1),
                    msg::io::wrongType(TAIWA_TRANSLATE_NOOP("taiwa::msg", "an object"), (*list)[i]));
            continue;
        }
        each(f.nested((*list)[i], prefix), i);
    }
}

}  // namespace taiwa::io
