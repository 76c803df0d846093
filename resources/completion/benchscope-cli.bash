# bash completion for benchscope-cli. Generated from the command registry by `benchscope-cli completion bash`;
# regenerate it rather than editing it. Use: source this file, or install it as
# /usr/share/bash-completion/completions/benchscope-cli.
_benchscope_cli() {
  local cur="${COMP_WORDS[COMP_CWORD]}"
  local commands="battery bench check compare completion devices efficiency figures frames headroom headroom-results help import job lens library peaks pipeline platforms power record-power remote report roofline run runs sensors sustain synth-frame synth-power"
  if [[ $COMP_CWORD -eq 1 ]]; then
    COMPREPLY=($(compgen -W "$commands --help --version" -- "$cur"))
    return
  fi
  local options=""
  case "${COMP_WORDS[1]}" in
    battery) options="--help --capacity-mah --cutoff-cell-volts --dod --extra-load --internal-mohm --json --mission --model --power-log --preset --save-preset --series --step --supply-volts --volts --watts --workspace" ;;
    bench) options="--help --arch --backend --batch --ceilings-only --columns --cpu --detect-scale --detect-workers --frames --input --isa --json --limit-us --load --model --no-ceilings --no-rt --platform --power --power-interval-ms --priority --rate --rounds --rows --runs --samples --seconds --step --sysfs-root --threads --updates --workers --workspace" ;;
    check) options="--help --remove-damaged" ;;
    compare) options="--help --all --alpha --every-point --json --threshold" ;;
    completion) options="--help" ;;
    devices) options="--help --isa --json --measure-ceilings --proc-root --sysfs-root --table --workspace" ;;
    efficiency) options="--help --json --supply-volts" ;;
    figures) options="--help --data --dpi --font-pt --format --height-mm --out --preset --quiet --template --width-mm" ;;
    frames) options="--help --lens --method --out --triptych --window" ;;
    headroom) options="--help --computation-us --cpu --deadline-us --detector --json --limit-us --load --load-command --no-idle --no-rt --platform --power --power-interval-ms --priority --rate --seconds --settle --sysfs-root --threads --workspace" ;;
    headroom-results) options="--help --json --kind --platform" ;;
    help) COMPREPLY=($(compgen -W "$commands" -- "$cur")); return ;;
    import) options="--help --copy-frames --keep-going --platform --quiet --raw-geometry" ;;
    job) options="--help --id --isa --jobs-dir --name --size --sysfs-root" ;;
    lens) options="--help --board --circle-fov --circle-radius --fix --fov --json --lens --max-bend --max-lines --min-length --min-level --model --out --propose --reject-lines --square" ;;
    library) options="--help --battery --budget --computer --csv --extra-load --figure --json --latex --min-fps --min-runtime" ;;
    peaks) options="--help --json --kind --precision" ;;
    pipeline) options="--help --backend --demosaic --detect-scale --detect-workers --detector --frames --json --lens --out --pattern --platform --policy --power --power-interval-ms --queue --synthetic --sysfs-root --workspace" ;;
    platforms) options="--help --battery --budget --candidates-csv --candidates-latex --csv --extra-load --json --latex --library --min-fps --min-runtime --mission --no-stored --require-loop --require-sustained --store --supply-volts --use-log --workspace" ;;
    power) options="--help --from --interval --json --min-phase --min-step --phases --query-gpu --supply-volts --to" ;;
    record-power) options="--help --events --interval-ms --out --quiet --seconds --sensor --sysfs-root --workspace" ;;
    remote) options="--help --desk-quiet --id --platform --remote-cli --ssh-config --synthetic --workspace" ;;
    report) options="--help --battery --budget --extra-load --font-pt --library --min-fps --min-runtime --mission --no-stored --out --pdf --quiet --require-loop --require-sustained --supply-volts --template" ;;
    roofline) options="--help --json" ;;
    run) options="--help --backend --device --events --isa --iterations --json --mib --no-warmup --out --points --power --power-interval-ms --quiet --repeats --sysfs-root --variant --workers --workspace" ;;
    runs) options="--help --clear --label --run" ;;
    sensors) options="--help --json --power --sensor --sysfs-root" ;;
    sustain) options="--help --detector --events --interval --json --load --platform --power --power-interval-ms --seconds --stable-percent --sysfs-root --throttle-threshold --workspace" ;;
    synth-frame) options="--help --bits --blur --board --lens --noise --out --pattern --pose --poses --scene --seed --size --square --supersample --vignetting" ;;
    synth-power) options="--help --out --platform --rate --samples --seed" ;;
  esac
  if [[ $cur == -* ]]; then
    COMPREPLY=($(compgen -W "$options" -- "$cur"))
  else
    COMPREPLY=($(compgen -f -- "$cur"))
  fi
}
complete -o filenames -F _benchscope_cli benchscope-cli
