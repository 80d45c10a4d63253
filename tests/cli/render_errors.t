#!/bin/sh
# render_errors.t - every class of bad option gets one line on stderr
# naming the option, the value and what is accepted; exit status 2;
# nothing on stdout.
. "$(dirname "$0")/lib.sh"

expect_usage_error "width not a number" "^rayo: --width: 'abc' is not a whole number; expected 1 to 65536$" --width abc
expect_usage_error "width partly a number" "--width: '12px'" -W 12px
expect_usage_error "width empty" "--width: ''" --width=
expect_usage_error "width zero" "--width: '0' is out of range; expected 1 to 65536" -W 0
expect_usage_error "width negative" "--width: '-5' is not a whole number" -W -5
expect_usage_error "width too large" "--width: '65537' is out of range" -W 65537
expect_usage_error "width huge" "--width: '99999999999999999999999' is out of range" -W 99999999999999999999999
expect_usage_error "height zero" "--height: '0' is out of range" -H 0
expect_usage_error "height too large" "--height: '70000' is out of range" --height 70000
expect_usage_error "more than 2^30 pixels" "--width 65536 --height 16385: 1073807360 pixels; expected at most 1073741824" -W 65536 -H 16385
expect_usage_error "fov NaN" "--fov: 'nan' is not a finite number" --fov nan
expect_usage_error "fov infinite" "--fov: 'inf' is not a finite number" --fov inf
expect_usage_error "fov zero" "--fov: '0' is out of range; expected degrees strictly between 0 and 180" --fov 0
expect_usage_error "fov negative" "--fov: '-10' is out of range" --fov -10
expect_usage_error "fov 180" "--fov: '180' is out of range" --fov 180
expect_usage_error "fov not a number" "--fov: 'wide' is not a finite number" --fov wide
expect_usage_error "radius zero" "--sphere: radius in '0,0,3,0' must be greater than 0" --sphere 0,0,3,0
expect_usage_error "radius negative" "--sphere: radius in '0,0,3,-1' must be greater than 0" --sphere 0,0,3,-1
expect_usage_error "sphere with 3 numbers" "--sphere: '1,2,3' has 3 numbers; expected 4: CX,CY,CZ,R" --sphere 1,2,3
expect_usage_error "sphere with 5 numbers" "--sphere: '1,2,3,4,5' has 5 numbers; expected 4" --sphere 1,2,3,4,5
expect_usage_error "sphere with an empty number" "--sphere: '' in '1,,3,4' is not a finite number; expected CX,CY,CZ,R" --sphere 1,,3,4
expect_usage_error "sphere with infinity" "--sphere: 'inf' in '0,0,inf,1' is not a finite number" --sphere 0,0,inf,1
expect_usage_error "sphere with NaN" "--sphere: 'NaN' in" --sphere 0,NaN,3,1
expect_usage_error "origin with 2 numbers" "--origin: '1,2' has 2 numbers; expected 3: X,Y,Z" --origin 1,2
expect_usage_error "origin infinite" "--origin: '-inf' in '0,0,-inf' is not a finite number" --origin 0,0,-inf
expect_usage_error "unknown long option" "unknown option '--bogus'" --bogus
expect_usage_error "unknown short option" "unknown option '-x'" -x
expect_usage_error "missing value" "'--width' needs a value" --width
expect_usage_error "unknown format" "--format: 'gif' is not accepted; expected pbm, png, bmp or jpeg" --format gif
expect_usage_error "unknown extension" "--output: cannot tell the format of 'out.gif' from its extension; expected .pbm, .png, .bmp or .jpg, or give --format" -o out.gif
expect_usage_error "no extension" "--output: cannot tell the format of 'out'" -o out
expect_usage_error "raw with png" "--raw: applies only to PBM output, not png" --raw -o x.png
expect_usage_error "threads zero" "--threads: '0' is out of range; expected 1 to 256" -j 0
expect_usage_error "a second positional argument" "unexpected argument 'extra'" render one.scene extra
expect_usage_error "unknown command" "unknown command 'rendr'" rendr
ok "$([ ! -e out.gif ] && [ ! -e out ] && [ ! -e x.png ]; echo $?)" "no output file left by refused runs"
done_testing
