// Command line `paddy doe ...` (CLI11), called by the paddy executable with argv[0] == "doe".
//   paddy doe design pb|bbd|ccd|factorial [--factors N | --names A,B,C] [--levels A=lo:hi ...]
//         [--center N] [--replicates N] [--seed S] [--alpha rotatable|face|VALUE]
//         [--ccd-type circumscribed|inscribed|face] [--runs N] [--generators D=ABC ...]
//         --csv OUT.csv [--json OUT.json]
//   paddy doe analyze DATA.csv --factors A,B,C --responses Y1,Y2
//         --model linear|linear+curvature|2fi|quadratic|"A,B,A:B" [--levels A=lo:hi ...]
//         [--json OUT.json] [--plots DIR]
//   paddy doe optimize FIT.json --goal Y1=target:231 [--goal ...] [--bounds A=lo:hi ...]
//         [--starts N] [--seed S] [--solutions N] [--json OUT.json] [--plots DIR]
//   paddy doe path FIT.json --response Y [--descent] [--key A --step S [--real]]
//         [--real-steps A=0.03 ...] [--origin A=x ...] [--steps N] [--csv OUT.csv]
//   paddy doe diagnose INPUT.json [--json OUT.json]   (naming a missing effect, discovery.hpp)
// Return value: 0 on success, 2 on bad input (the message goes to stderr).
#pragma once
#include <ostream>
#include <string>
#include <vector>

namespace paddy::doe {

int runCli(int argc, char** argv);
/// Same with explicit streams; args[0] must be "doe".
int runCli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace paddy::doe
