// The CEC 2006 suite's table: each problem's box (Table 4 of Liang et al. 2006), x* and f* (its
// problem texts) and constraint counts (its Table 3).
#include "problems/continuous/cec2006/cec2006_detail.hpp"

#include <array>
#include <string>

#include "framework/error.hpp"
#include "problems/continuous/cec2006/cec2006.hpp"

namespace pride::continuous::cec2006::detail {

namespace {

// ---- Boxes (the report's Table 4) and x* (its problem texts).
template <std::size_t N>
constexpr std::array<double, N> filled(double v) {
    std::array<double, N> a{};
    for (double& e : a) e = v;
    return a;
}

constexpr std::array<double, 13> kLo01 = filled<13>(0.0);
constexpr std::array<double, 13> kHi01 = {1, 1, 1, 1, 1, 1, 1, 1, 1, 100, 100, 100, 1};
constexpr std::array<double, 13> kX01 = {1, 1, 1, 1, 1, 1, 1, 1, 1, 3, 3, 3, 1};

constexpr std::array<double, 20> kLo02 = filled<20>(0.0);
constexpr std::array<double, 20> kHi02 = filled<20>(10.0);
constexpr std::array<double, 20> kX02 = {3.16246061572185, 3.12833142812967, 3.09479212988791, 3.06145059523469,
                                         3.02792915885555, 2.99382606701730, 2.95866871765285, 2.92184227312450,
                                         0.49482511456933, 0.48835711005490, 0.48231642711865, 0.47664475092742,
                                         0.47129550835493, 0.46623099264167, 0.46142004984199, 0.45683664767217,
                                         0.45245876903267, 0.44826762241853, 0.44424700958760, 0.44038285956317};

constexpr std::array<double, 10> kLo03 = filled<10>(0.0);
constexpr std::array<double, 10> kHi03 = filled<10>(1.0);
constexpr std::array<double, 10> kX03 = {
    0.31624357647283069, 0.316243577414338339, 0.316243578012345927, 0.316243575664017895, 0.316243578205526066,
    0.31624357738855069, 0.316243575472949512, 0.316243577164883938, 0.316243578155920302, 0.316243576147374916};

constexpr std::array<double, 5> kLo04 = {78, 33, 27, 27, 27};
constexpr std::array<double, 5> kHi04 = {102, 45, 45, 45, 45};
constexpr std::array<double, 5> kX04 = {78, 33, 29.9952560256815985, 45, 36.7758129057882073};

constexpr std::array<double, 4> kLo05 = {0, 0, -0.55, -0.55};
constexpr std::array<double, 4> kHi05 = {1200, 1200, 0.55, 0.55};
constexpr std::array<double, 4> kX05 = {679.945148297028709, 1026.06697600004691, 0.118876369094410433,
                                        -0.39623348521517826};

constexpr std::array<double, 2> kLo06 = {13, 0};
constexpr std::array<double, 2> kHi06 = {100, 100};
constexpr std::array<double, 2> kX06 = {14.09500000000000064, 0.8429607892154795668};

constexpr std::array<double, 10> kLo07 = filled<10>(-10.0);
constexpr std::array<double, 10> kHi07 = filled<10>(10.0);
constexpr std::array<double, 10> kX07 = {2.17199634142692,  2.3636830416034,  8.77392573913157, 5.09598443745173,
                                         0.990654756560493, 1.43057392853463, 1.32164415364306, 9.82872576524495,
                                         8.2800915887356,   8.3759266477347};

constexpr std::array<double, 2> kLo08 = {0, 0};
constexpr std::array<double, 2> kHi08 = {10, 10};
constexpr std::array<double, 2> kX08 = {1.22797135260752599, 4.24537336612274885};

constexpr std::array<double, 7> kLo09 = filled<7>(-10.0);
constexpr std::array<double, 7> kHi09 = filled<7>(10.0);
constexpr std::array<double, 7> kX09 = {2.33049935147405174, 1.95137236847114592,   -0.477541399510615805,
                                        4.36572624923625874, -0.624486959100388983, 1.03813099410962173,
                                        1.5942266780671519};

constexpr std::array<double, 8> kLo10 = {100, 1000, 1000, 10, 10, 10, 10, 10};
constexpr std::array<double, 8> kHi10 = {10000, 10000, 10000, 1000, 1000, 1000, 1000, 1000};
constexpr std::array<double, 8> kX10 = {579.306685017979589, 1359.97067807935605, 5109.97065743133317,
                                        182.01769963061534,  295.601173702746792, 217.982300369384632,
                                        286.41652592786852,  395.601173702746735};

constexpr std::array<double, 2> kLo11 = {-1, -1};
constexpr std::array<double, 2> kHi11 = {1, 1};
constexpr std::array<double, 2> kX11 = {-0.707036070037170616, 0.500000004333606807};

constexpr std::array<double, 3> kLo12 = {0, 0, 0};
constexpr std::array<double, 3> kHi12 = {10, 10, 10};
constexpr std::array<double, 3> kX12 = {5, 5, 5};

constexpr std::array<double, 5> kLo13 = {-2.3, -2.3, -3.2, -3.2, -3.2};
constexpr std::array<double, 5> kHi13 = {2.3, 2.3, 3.2, 3.2, 3.2};
constexpr std::array<double, 5> kX13 = {-1.71714224003, 1.59572124049468, 1.8272502406271, -0.763659881912867,
                                        -0.76365986736498};

constexpr std::array<double, 10> kLo14 = filled<10>(0.0);
constexpr std::array<double, 10> kHi14 = filled<10>(10.0);
constexpr std::array<double, 10> kX14 = {
    0.0406684113216282,   0.147721240492452,  0.783205732104114,  0.00141433931889084, 0.485293636780388,
    0.000693183051556082, 0.0274052040687766, 0.0179509660214818, 0.0373268186859717,  0.0968844604336845};

constexpr std::array<double, 3> kLo15 = {0, 0, 0};
constexpr std::array<double, 3> kHi15 = {10, 10, 10};
constexpr std::array<double, 3> kX15 = {3.51212812611795133, 0.216987510429556135, 3.55217854929179921};

constexpr std::array<double, 5> kLo16 = {704.4148, 68.6, 0, 193, 25};
constexpr std::array<double, 5> kHi16 = {906.3855, 288.88, 134.75, 287.0966, 84.1988};
constexpr std::array<double, 5> kX16 = {705.174537070090537, 68.5999999999999943, 102.899999999999991,
                                        282.324931593660324, 37.5841164258054832};

constexpr std::array<double, 6> kLo17 = {0, 0, 340, 340, -1000, 0};
constexpr std::array<double, 6> kHi17 = {400, 1000, 420, 420, 1000, 0.5236};
constexpr std::array<double, 6> kX17 = {201.784467214523659,  99.9999999999999005,  383.071034852773266, 420,
                                        -10.9076584514292652, 0.0731482312084287128};

constexpr std::array<double, 9> kLo18 = {-10, -10, -10, -10, -10, -10, -10, -10, 0};
constexpr std::array<double, 9> kHi18 = {10, 10, 10, 10, 10, 10, 10, 10, 20};
constexpr std::array<double, 9> kX18 = {-0.657776192427943163, -0.153418773482438542, 0.323413871675240938,
                                        -0.946257611651304398, -0.657776194376798906, -0.753213434632691414,
                                        0.323413874123576972,  -0.346462947962331735, 0.59979466285217542};

constexpr std::array<double, 15> kLo19 = filled<15>(0.0);
constexpr std::array<double, 15> kHi19 = filled<15>(10.0);
constexpr std::array<double, 15> kX19 = {1.66991341326291344e-17, 3.95378229282456509e-16, 3.94599045143233784,
                                         1.06036597479721211e-16, 3.2831773458454161,      9.99999999999999822,
                                         1.12829414671605333e-17, 1.2026194599794709e-17,  2.50706276000769697e-15,
                                         2.24624122987970677e-15, 0.370764847417013987,    0.278456024942955571,
                                         0.523838487672241171,    0.388620152510322781,    0.298156764974678579};

constexpr std::array<double, 24> kLo20 = filled<24>(0.0);
constexpr std::array<double, 24> kHi20 = filled<24>(10.0);
constexpr std::array<double, 24> kX20 = {1.28582343498528086e-18,
                                         4.83460302526130664e-34,
                                         0,
                                         0,
                                         6.30459929660781851e-18,
                                         7.57192526201145068e-34,
                                         5.03350698372840437e-34,
                                         9.28268079616618064e-34,
                                         0,
                                         1.76723384525547359e-17,
                                         3.55686101822965701e-34,
                                         2.99413850083471346e-34,
                                         0.158143376337580827,
                                         2.29601774161699833e-19,
                                         1.06106938611042947e-18,
                                         1.31968344319506391e-18,
                                         0.530902525044209539,
                                         0,
                                         2.89148310257773535e-18,
                                         3.34892126180666159e-18,
                                         0,
                                         0.310999974151577319,
                                         5.41244666317833561e-05,
                                         4.84993165246959553e-16};

constexpr std::array<double, 7> kLo21 = {0, 0, 0, 100, 6.3, 5.9, 4.5};
constexpr std::array<double, 7> kHi21 = {1000, 40, 40, 300, 6.7, 6.4, 6.25};
constexpr std::array<double, 7> kX21 = {193.724510070034967, 5.56944131553368433e-27, 17.3191887294084914,
                                        100.047897801386839, 6.68445185362377892,     5.99168428444264833,
                                        6.21451648886070451};

constexpr std::array<double, 22> kLo22 = {0,   0, 0, 0, 0,    0,    0,    100,  100,  100.01, 100,
                                          100, 0, 0, 0, 0.01, 0.01, -4.7, -4.7, -4.7, -4.7,   -4.7};
constexpr std::array<double, 22> kHi22 = {20000, 1e6, 1e6, 1e6, 4e7, 4e7, 4e7,  299.99, 399.99, 300,  400,
                                          600,   500, 500, 500, 300, 400, 6.25, 6.25,   6.25,   6.25, 6.25};
constexpr std::array<double, 22> kX22 = {
    236.430975504001054, 135.82847151732463,  204.818152544824585, 6446.54654059436416, 3007540.83940215595,
    4074188.65771341929, 32918270.5028952882, 130.075408394314167, 170.817294970528621, 299.924591605478554,
    399.258113423595205, 330.817294971142758, 184.51831230897065,  248.64670239647424,  127.658546694545862,
    269.182627528746707, 160.000016724090955, 5.29788288102680571, 5.13529735903945728, 5.59531526444068827,
    5.43444479314453499, 5.07517453535834395};

constexpr std::array<double, 9> kLo23 = {0, 0, 0, 0, 0, 0, 0, 0, 0.01};
constexpr std::array<double, 9> kHi23 = {300, 300, 100, 200, 100, 300, 100, 200, 0.03};
constexpr std::array<double, 9> kX23 = {
    0.00510000000000259465,  99.9947000000000514,     9.01920162996045897e-18, 99.9999000000000535,
    0.000100000000027086086, 2.75700683389584542e-14, 99.9999999999999574,     200,
    0.0100000100000100008};

constexpr std::array<double, 2> kLo24 = {0, 0};
constexpr std::array<double, 2> kHi24 = {3, 4};
constexpr std::array<double, 2> kX24 = {2.32952019747762, 3.17849307411774};

// Counts: Table 3's LI + NI and LE + NE. f*: the problem texts' (g20: Table 4's).
constexpr Spec kSpecs[kProblems] = {
    {"g01", 9, 0, -15.0, kLo01, kHi01, kX01},
    {"g02", 2, 0, -0.80361910412559, kLo02, kHi02, kX02},
    {"g03", 0, 1, -1.00050010001000, kLo03, kHi03, kX03},
    {"g04", 6, 0, -30665.53867178332, kLo04, kHi04, kX04},
    {"g05", 2, 3, 5126.4967140071, kLo05, kHi05, kX05},
    {"g06", 2, 0, -6961.81387558015, kLo06, kHi06, kX06},
    {"g07", 8, 0, 24.30620906818, kLo07, kHi07, kX07},
    {"g08", 2, 0, -0.0958250414180359, kLo08, kHi08, kX08},
    {"g09", 4, 0, 680.630057374402, kLo09, kHi09, kX09},
    {"g10", 6, 0, 7049.24802052867, kLo10, kHi10, kX10},
    {"g11", 0, 1, 0.7499, kLo11, kHi11, kX11},
    {"g12", 1, 0, -1.0, kLo12, kHi12, kX12},
    {"g13", 0, 3, 0.053941514041898, kLo13, kHi13, kX13},
    {"g14", 0, 3, -47.7648884594915, kLo14, kHi14, kX14},
    {"g15", 0, 2, 961.715022289961, kLo15, kHi15, kX15},
    {"g16", 38, 0, -1.90515525853479, kLo16, kHi16, kX16},
    {"g17", 0, 4, 8853.53967480648, kLo17, kHi17, kX17},
    {"g18", 13, 0, -0.866025403784439, kLo18, kHi18, kX18},
    {"g19", 5, 0, 32.6555929502463, kLo19, kHi19, kX19},
    {"g20", 6, 14, 0.2049794002, kLo20, kHi20, kX20},
    {"g21", 1, 5, 193.724510070035, kLo21, kHi21, kX21},
    {"g22", 1, 19, 236.430975504001, kLo22, kHi22, kX22},
    {"g23", 2, 4, -400.055099999999584, kLo23, kHi23, kX23},
    {"g24", 2, 0, -5.50801327159536, kLo24, kHi24, kX24},
};

}  // namespace

const Spec& spec(int number) {
    require(
        number >= 1 && number <= kProblems, "problem",
        "CEC 2006 has problems 1 to " + std::to_string(kProblems) + " (g01 ... g24), got " + std::to_string(number));
    return kSpecs[number - 1];
}

}  // namespace pride::continuous::cec2006::detail
