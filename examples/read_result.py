#!/usr/bin/python3
"""A result file of `caskdem ensemble` in pandas: one row per realisation, units beside, and the
fitted curves of each limit state. Default: the main job's results/model-1-3-builtin.h5
(scripts/main.sh makes it).
Run: /usr/bin/python3 examples/read_result.py [RESULT.h5]
"""

import sys

import pandas

import caskdem


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else "results/model-1-3-builtin.h5"
    try:
        result = caskdem.read_result(path)
    except ValueError as error:
        print(f"read_result.py: {error} (scripts/main.sh writes the default file)", file=sys.stderr)
        return 2
    realisations = result["realisations"]
    table = pandas.DataFrame(realisations)
    units = realisations.units
    print(f"{path}: {result.attrs['title']}")
    print(f"{len(table)} realisations; intensity measure {result.attrs['intensity_measure']} "
          f"[{units['level']}], model scale 1/{result.attrs.get('model_scale', 1):g}")
    table["tipped_over"] = table["status"] == 1
    by_level = table.groupby("level").agg(realisations=("status", "size"), tipped=("tipped_over", "sum"),
                                          max_slide_m=("max_abs_slide", "max"))
    print(by_level.to_string())
    states = sorted(result["limit_states"].items(), key=lambda item: item[1].attrs["order"])  # the file's order
    for name, state in states:
        a = state.attrs
        if a["fitted"]:
            verdict = "REJECTED" if a["fit_rejected"] else "holds"
            print(f"{name}: median {a['median']:.4g} {a['intensity_unit']}, beta {a['log_std']:.3f}, "
                  f"fit test p {a['fit_test_p_value']:.3f} ({verdict})")
        else:
            print(f"{name}: no curve ({a.get('not_fitted_because', '')})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
