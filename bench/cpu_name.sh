# Sourced by bench/run and bench/run-cores: the CPU that runs, as `cpu`, the name of its results
# folder under bench/results/, and `cpu_context`, what the summary prints about it.
#
# The brand string alone can be shared by different CPUs ("AMD EPYC" is a Zen 3 and a Zen 4
# virtual machine): family and model number follow it in the folder's name.
cpuinfo_field() { sed -n "s/^$1[[:space:]]*:[[:space:]]*//p" /proc/cpuinfo | head -n 1; }
model=$(cpuinfo_field 'model name')
[[ -n $model ]] || model="$(uname -m)-unknown"
family=$(cpuinfo_field 'cpu family')
number=$(cpuinfo_field 'model')
stepping=$(cpuinfo_field 'stepping')
name=$model
[[ -n $family && -n $number ]] && name="${model}_family${family}_model${number}"
cpu=$(printf '%s' "$name" | tr -c 'A-Za-z0-9_-' '_' | tr -s '_' | sed 's/^_//; s/_$//')
isa_flags=$(grep -m1 -o -w -E 'avx512f|avx512bw|avx512vl|avx2|fma|sse4_1' /proc/cpuinfo | sort -u |
  tr '\n' ' ' || true)
cpu_context="$model; family ${family:-?} model ${number:-?} stepping ${stepping:-?}; ${isa_flags% }"
# (Google Benchmark splits --benchmark_context at commas: the value must hold none.)
cpu_context=${cpu_context//,/}
