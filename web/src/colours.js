// One colour per component, x red, y green, z blue, as the rendered body axes: ω_x, ω_y and ω_z
// in every picture. The channels of src/common/colour.hpp's kComponentColours × 255, rounded;
// tests/common/colour_test.cpp holds the two (and the notebook's) to the same colours.
export const OMEGA_COLOURS = ['#d9261a', '#1a9933', '#2659e6'];
