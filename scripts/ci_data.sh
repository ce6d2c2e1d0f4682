# Sourced by .ci/run: exports PRIDE_DATA as the absolute path of the folder of public data given as
# $1, and PRIDE_CEC2017_DATA / PRIDE_CEC2022_DATA as its official CEC folders where it holds them.
PRIDE_DATA=$(cd "$1" && pwd -P)
export PRIDE_DATA
if [[ -d $PRIDE_DATA/cec2017/input_data ]]; then export PRIDE_CEC2017_DATA=$PRIDE_DATA/cec2017/input_data; fi
if [[ -d $PRIDE_DATA/cec2022/input_data ]]; then export PRIDE_CEC2022_DATA=$PRIDE_DATA/cec2022/input_data; fi
