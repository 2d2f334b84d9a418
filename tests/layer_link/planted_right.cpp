// Planted in the model layer by tests/layer_link: a call to the model itself,
// which the layer's link check must let through.
#include "model/codes.h"

int plantedRightCall(int code) { return taiwa::hasRoughing(taiwa::toolUseFromCode(code).value_or(taiwa::ToolUse::Standard)) ? 1 : 0; }
