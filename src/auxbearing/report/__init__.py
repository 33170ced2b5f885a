"""Reports: the data model of a report and its HTML rendering."""
