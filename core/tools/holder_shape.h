// The shapes above a milling tool's flutes that must not touch the stock:
// the shank (the tool's own body between the flutes and the holder) and the
// holder's nose (collet nut, shrink-fit sleeve, side-lock body), each as a
// cylinder, for the verification's collision check (verify/). The library's
// holder diameter and length when it has them; else the nose is read from
// the holder's name by the rules of docs/verification.md, and a name the
// rules do not know gets a nose wide enough to hold any such holder (so a
// collision is never missed for want of data).
#pragma once

#include "model/tool.h"

namespace taiwa::tools {

struct HolderShape {
    double shankDiameter = 0.0;  // from the flute length up to the stick-out
    double noseDiameter = 0.0;   // the holder's, from the stick-out up
    double noseLength = 0.0;     // how far up the nose reaches above the stick-out
    bool known = false;          // the name matched a rule
};

HolderShape holderShape(const Tool& tool);

}  // namespace taiwa::tools
