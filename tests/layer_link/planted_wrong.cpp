// Planted in the model layer by tests/layer_link: a wrong-way call, from the
// model up to the post (core/post/post.h declares it; declared here by hand,
// so that no include names the post), which the layer's link check must
// refuse with an undefined reference.
#include <string>
#include <vector>

namespace taiwa {
std::vector<std::string> dialectNames();
}

int plantedWrongCall() { return static_cast<int>(taiwa::dialectNames().size()); }
