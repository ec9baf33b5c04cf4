# SPDX-License-Identifier: Apache-2.0
# cmake -DVRREG=<vrreg> -DHELP2MAN=<help2man> -DOUT=<dir/vrreg.1> -P VrregManPage.cmake
# writes vrreg(1) from `vrreg --help`, with a COMMANDS section made of each command's --help,
# then <OUT>.gz (gzip -9n: no name or time stamp, as Debian requires).
get_filename_component(dir ${OUT} DIRECTORY)
file(MAKE_DIRECTORY ${dir})
execute_process(COMMAND ${VRREG} --help OUTPUT_VARIABLE help COMMAND_ERROR_IS_FATAL ANY)
# The command names: the lines after "SUBCOMMANDS:" (CLI11), the first word of each.
string(REGEX REPLACE ".*\n[A-Za-z]*[Ss][Uu][Bb][Cc][Oo][Mm][Mm][Aa][Nn][Dd][Ss]:\n" "" listing "${help}")
string(REGEX MATCHALL "(^|\n)  [a-z][a-z-]*" names "${listing}")
set(include "[COMMANDS]\n")
foreach(name IN LISTS names)
  string(STRIP "${name}" name)
  execute_process(COMMAND ${VRREG} ${name} --help OUTPUT_VARIABLE command_help
                  COMMAND_ERROR_IS_FATAL ANY)
  # Each command's help as a literal block under its name (.nf keeps the columns).
  # groff: a backslash is \e; a line starting with . or ' would be a request, \& stops that.
  string(REPLACE "\\" "\\e" command_help "${command_help}")
  string(REPLACE "\n." "\n\\&." command_help "${command_help}")
  string(REPLACE "\n'" "\n\\&'" command_help "${command_help}")
  string(APPEND include ".SS ${name}\n.nf\n${command_help}.fi\n")
endforeach()
string(APPEND include "[SEE ALSO]\n`vrreg COMMAND --help` prints each command's part of this page. "
       "The project's docs/ describe the method, the file formats and the library.\n")
file(WRITE ${dir}/vrreg.h2m "${include}")
execute_process(COMMAND ${HELP2MAN} --no-info --section=1
                        "--name=vision-robot registration with the RRBC correction"
                        --include=${dir}/vrreg.h2m --output=${OUT} ${VRREG}
                COMMAND_ERROR_IS_FATAL ANY)
execute_process(COMMAND gzip -9nf ${OUT} COMMAND_ERROR_IS_FATAL ANY)
