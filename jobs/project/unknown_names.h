// What a project reader does with attributes and elements it does not know, and with a project
// version newer than its own: refuse them (the default: a misspelt or unsupported name must not
// build another part than the one written), or read on and warn (the CLI's --lenient).
#pragma once

namespace polarform {

enum class UnknownNames { refuse, warn };

}  // namespace polarform
