"""What every room stands on: errors, quantities with units, parameter tables, files and interrupts."""
