#donotrun
// Constants for fold_helpers.frag, included from the same folder.
const float FOLD_LIMIT_DEFAULT = 1.0;
#define FOLD_HELPERS_CONSTANTS
float foldConstantsMarker() { return FOLD_LIMIT_DEFAULT; }
