// The "names" map of the data files (materials, machines): a language code
// to the name in that language, read and written as JSON. A map that is not
// one is refused saying what is wrong with it.
#pragma once

#include "model/local_name.h"
#include "model/result.h"

#include <nlohmann/json.hpp>

namespace taiwa {

// `value` as names: an object of language codes ("ja", "zh", "zh-TW": two or
// three small letters, a region after a dash) to texts that are not empty.
// The failure says what is wrong without naming the key (the caller does).
Result<LocalNames> localNamesFrom(const nlohmann::json& value);
// The map as the data files write it.
nlohmann::json localNamesJson(const LocalNames& names);

}  // namespace taiwa
