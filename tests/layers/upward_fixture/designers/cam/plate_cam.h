// The designer header that upward.h includes (any content: only the include is checked).
#pragma once
