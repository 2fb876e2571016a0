// first/shared.glsl: the first search-path folder wins
const int sharedFrom = 1;
