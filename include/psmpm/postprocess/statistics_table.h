// ---------------------------------------------------------------------
// psmpm: Material Point Method with Powell-Sabin splines on triangles.
// ---------------------------------------------------------------------
#ifndef psmpm_postprocess_statistics_table_h
#define psmpm_postprocess_statistics_table_h

#include <cstdint>
#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace psmpm
{
  namespace Postprocess
  {
    /**
     * The table of statistics.txt: one row per step, the columns in the
     * order of their first value, written in the layout of deal.II's
     * TableHandler::table_with_separate_column_description (a "# j: name"
     * line per column, then the rows, every entry right-aligned to its
     * column's widest entry and followed by a space), with the same
     * number formats (scientific or fixed, a precision per column).
     *
     * Why not TableHandler: it formats every value through a
     * std::ostringstream when it is added and finds its column by a
     * std::map look-up; on small scenes, which record a row per step,
     * that was 5 % of all instructions of a run (the large vibrating bar:
     * 0.11M instructions per step). Here a value is stored as a number
     * and formatted once, with std::to_chars, when a write first needs
     * it; the column of the next value is guessed from the order of the
     * last row.
     */
    class StatisticsTable
    {
    public:
      void
      add_value(const std::string &key, const double value);
      void
      add_value(const std::string &key, const unsigned int value);
      void
      add_value(const std::string &key, const int value);
      void
      add_value(const std::string &key, const std::uint64_t value);
      /// A text entry ("-": not computed at this step).
      void
      add_value(const std::string &key, const std::string &text);

      /// "name = value" of the first column whose newest entry is a
      /// number that is not finite (inf or nan), or "": such a row is no
      /// result (the simulator stops the run on it).
      std::string
      non_finite_in_last_entries() const;

      /// Format of column @p key (which must exist): scientific or fixed.
      void
      set_scientific(const std::string &key, const bool scientific);
      /// Digits after the decimal point of column @p key (default 4).
      void
      set_precision(const std::string &key, const unsigned int precision);

      /// Rows (the longest column's entries).
      unsigned int
      n_rows() const;

      /// The whole table, in the layout described above: write_header(),
      /// then write_rows() of every row.
      void
      write_text(std::ostream &out) const;

      /// The column descriptions ("# j: name" lines).
      void
      write_header(std::ostream &out) const;

      /// Rows [@p begin, @p end) (at most n_rows()).
      void
      write_rows(std::ostream      &out,
                 const unsigned int begin,
                 const unsigned int end) const;

      /**
       * What fixes the text of the rows written so far: the columns'
       * names, formats and widths, and, where a column has fewer entries
       * than the table has rows (its entries would fill rows that are
       * already written), every column's length. GrowingTextFile appends
       * new rows only while this stays equal.
       */
      std::string
      layout() const;

      /// Every entry with its type and every column format (checkpoints).
      std::string
      to_bytes() const;
      /// Inverse of to_bytes(); throws on damaged bytes.
      void
      from_bytes(const std::string &bytes);

    private:
      enum Kind : std::uint8_t
      {
        real,
        signed_integer,
        unsigned_integer,
        text
      };

      struct Column
      {
        std::string  name;
        bool         scientific = false;
        unsigned int precision  = 4;
        /// Per entry: its kind and its bits (a double's, an integer's,
        /// or for text the index in texts).
        std::vector<std::uint8_t>  kinds;
        std::vector<std::uint64_t> bits;
        std::vector<std::string>   texts;
        /// Entries formatted so far (in the current format) and the
        /// widest of them.
        mutable std::vector<std::string> formatted;
        mutable std::size_t              width = 0;

        void
        invalidate() const
        {
          formatted.clear();
          width = 0;
        }
        void
        format_pending() const;
      };

      /// The column of @p key, created at the end if new.
      Column &
      column(const std::string &key);
      void
      add(const std::string &key, const Kind kind, const std::uint64_t bits);
      Column &
      existing_column(const std::string &key);

      std::vector<Column>                 columns;
      std::map<std::string, unsigned int> index;
      /// The column that received the last value.
      unsigned int last = 0;
    };
  } // namespace Postprocess
} // namespace psmpm

#endif
