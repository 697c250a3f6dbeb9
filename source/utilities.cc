#include <deal.II/base/exceptions.h>

#include <ring_contact/utilities.h>

#include <sstream>

namespace RingContact
{
  std::string
  one_line_message(const std::exception &e)
  {
    std::string text;
    if (const auto *deal_ii = dynamic_cast<const dealii::ExceptionBase *>(&e))
      {
        std::ostringstream out;
        deal_ii->print_info(out);
        text = out.str();
      }
    else
      text = e.what();
    // Collapse all whitespace runs into single spaces.
    std::string line;
    bool        space = false;
    for (const char c : text)
      if (std::isspace(static_cast<unsigned char>(c)))
        space = !line.empty();
      else
        {
          if (space)
            line += ' ';
          line += c;
          space = false;
        }
    return line;
  }
} // namespace RingContact
