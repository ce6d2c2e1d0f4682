#include "cli/flags.hpp"

#include <map>

namespace pride::cli {

std::string user_message(const InputError& e) {
    static const std::map<std::string, std::string> flags{{"dim", "--dim"},
                                                          {"problem", "--problem"},
                                                          {"algo", "--algo"},
                                                          {"start", "--start"},
                                                          {"goal", "--goal"},
                                                          {"objective", "--objective"},
                                                          {"encoding", "--encoding"},
                                                          {"connector", "--connector"},
                                                          {"init", "--init"},
                                                          {"waypoints", "--waypoints"},
                                                          {"weights", "--weights"},
                                                          {"lambda", "--lambda"},
                                                          {"inflate", "--inflate"},
                                                          {"iterations", "--iters"},
                                                          {"evaluations", "--evals"},
                                                          {"wall_ms", "--wall-ms"},
                                                          {"target", "--target"},
                                                          {"oracle", "--oracle"},
                                                          {"seed", "--seed"},
                                                          {"map", "--map"},
                                                          {"jobs", "--jobs"},
                                                          {"threads", "--threads"},
                                                          {"instance", "--instance"},
                                                          {"objectives", "--objectives"}};
    const std::string& where = e.where();
    if (where.empty()) return e.what();
    const auto space = where.find(' ');
    const std::string head = where.substr(0, space), rest = space == std::string::npos ? "" : where.substr(space);
    if (head == "parameter") return "--param" + rest + ": " + e.detail();
    const auto it = flags.find(head);
    if (it == flags.end()) return e.what();
    return it->second + rest + ": " + e.detail();
}

}  // namespace pride::cli
