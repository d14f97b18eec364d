#pragma once
// Moved to costmodel/GiVolumeLod.h (GL-free, shared by the renderer and the cost model).
#include "costmodel/GiVolumeLod.h"
