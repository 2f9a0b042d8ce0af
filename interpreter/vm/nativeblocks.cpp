// The standard timers run from nativeblocks.h (inline, so the VM's handlers inline them).
#include "interpreter/vm/nativeblocks.h"
