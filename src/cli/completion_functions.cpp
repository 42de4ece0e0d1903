// The fixed shell functions at the end of the completion script: they read the
// tables completion_script.cpp writes before them.
#include "docs.hpp"


namespace cic::cli::docs {

const char* const kCompletionFunctions = R"BASH(# COMPREPLY from the words in $1 that start with $cur. When $cur holds
# an '=' (a word break for bash), only the part after it is replaced.
_cic_reply() {
    local w prefix=""
    COMPREPLY=()
    [[ $cur == *=* && $COMP_WORDBREAKS == *=* ]] && prefix=${cur%=*}=
    for w in $1; do
        [[ $w == "$cur"* ]] && COMPREPLY+=("${w#"$prefix"}")
    done
}

_cic_files() {   # $1: file or dir
    local IFS=$'\n'
    compopt -o filenames 2>/dev/null
    if [[ $1 == dir ]]; then
        COMPREPLY=($(compgen -d -- "$cur"))
    else
        COMPREPLY=($(compgen -f -- "$cur"))
    fi
}

# Files, and the installed settings files by name (cic --settings NAME.xml finds them).
_cic_settings_files() {
    _cic_files file
    local exe f
    exe=$(type -P cic) || return 0
    for f in "$(dirname "$(readlink -f "$exe")")"/../share/cic/settings/*.xml; do
        [[ -f $f ]] || continue
        f=${f##*/}
        [[ $f == "$cur"* && ! -e $f ]] && COMPREPLY+=("$f")
    done
}

_cic() {
    # Words as typed (quotes aside), not split at '=' as COMP_WORDS is.
    local line=${COMP_LINE:0:COMP_POINT}
    local -a words
    read -r -a words <<< "$line"
    local cur=""
    [[ $line == *[[:space:]] ]] || { cur=${words[-1]}; unset 'words[-1]'; }

    local scope="" i w kind expect=""
    for ((i = 1; i < ${#words[@]}; i++)); do
        w=${words[i]}
        if [[ -n $expect ]]; then expect=""; continue; fi
        if [[ $w == -* && $w != *=* ]]; then
            kind=$(_cic_value_kind "$scope" "$w")
            [[ -z $kind ]] && [[ -n $scope ]] && kind=$(_cic_value_kind "" "$w")
            [[ -n $kind ]] && expect=$w
        elif [[ -z $scope && " $_cic_commands " == *" $w "* ]]; then
            scope=$w
        fi
    done

    # The value of an option: the option word before, or --opt=value.
    local opt=$expect
    if [[ -z $opt && $cur == --*=* ]]; then
        opt=${cur%%=*}
        cur=${cur#*=}
    fi
    if [[ -n $opt ]]; then
        kind=$(_cic_value_kind "$scope" "$opt")
        [[ -z $kind ]] && kind=$(_cic_value_kind "" "$opt")
        case $kind in
            keys)
                if [[ $cur == *=* ]]; then
                    local key=${cur%%=*} v values=""
                    for v in $(_cic_key_values "$key"); do values+=" $key=$v"; done
                    _cic_reply "$values"
                else
                    _cic_reply "$_cic_keys"
                    compopt -o nospace 2>/dev/null
                fi ;;
            settings) _cic_settings_files ;;
            file | dir) _cic_files "$kind" ;;
            *) COMPREPLY=() ;;
        esac
        return 0
    fi

    if [[ $cur == -* ]]; then
        _cic_reply "$(_cic_options "$scope")"
    elif [[ -z $scope ]]; then
        _cic_reply "$_cic_commands"
    else
        kind=$(_cic_positional_kind "$scope")
        if [[ -n $kind ]]; then _cic_files "$kind"; else COMPREPLY=(); fi
    fi
    return 0
}

complete -F _cic cic
)BASH";

} // namespace cic::cli::docs
