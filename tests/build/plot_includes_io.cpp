// Compiled twice by the build tests: linked to magnus_plot it must fail (plot takes data and cannot see
// io/), linked to magnus_app it must compile. Together they show that plot/ reads no files.
#include "io/rotor_data.hpp"

int main() { return int(magnus::rotor_data_path().empty()); }
