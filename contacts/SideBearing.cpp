// SideBearing is header-only; this unit keeps one source per element.
#include "contacts/SideBearing.h"
