// Objects nested in an object of a job document, for the readers of the job
// file and of the modules' units: the object at a key, or each object of an
// array, with its fields at their path ("clamping.", "rows[2]."). A value of
// the wrong kind is reported on its field, as json_fields.h's accessors do.
#pragma once

#include "io/json_fields.h"

#include <cstddef>
#include <functional>
#include <optional>

namespace taiwa::io {

// The fields of the object at `key` (their paths "key."); nothing when the
// key is absent, or when its value is not an object (reported as not
// `what`, by default "an object").
std::optional<ObjectFields> objectAt(const ObjectFields& f, const char* key, const char* what = nullptr);

// Each object of the array at `key` with its fields (their paths
// "key[2].", counted from 1) and its 0-based index. A value that is not an
// array (reported as not `what`; when absent, only if `required`) and an
// item that is not an object are reported.
void eachObject(const ObjectFields& f, const char* key, const char* what, bool required,
                const std::function<void(const ObjectFields& item, std::size_t index)>& each);

}  // namespace taiwa::io
