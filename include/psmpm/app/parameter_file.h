// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_app_parameter_file_h
#define psmpm_app_parameter_file_h

#include <string>

namespace psmpm
{
  namespace App
  {
    /**
     * Refuse a parameter file that deal.II's ParameterHandler would not
     * survive or would misread, before it reads it:
     * * a file that is not a regular file (a FIFO or device would block
     *   or never end), also as the target of an `include` line (taken
     *   relative to the working directory, as ParameterHandler opens it);
     * * `include` lines that include a file again (the file itself, or
     *   a cycle through others): ParameterHandler would recurse until the
     *   stack overflows; at most 16 levels;
     * * a JSON file (`.json`) nested deeper than 32 levels (boost's
     *   reader recurses per level), or with a value that is null or an
     *   array (the reader would take null as the text "null"): psmpm
     *   reads an object of subsections (objects) and entries (strings,
     *   numbers or booleans).
     * Throws ExcMessage naming the file, the line or entry path.
     */
    void
    check_parameter_file(const std::string &file);
  } // namespace App
} // namespace psmpm

#endif
