"""Documents for people: the HTML engine, the verification's and the campaign's reports, the machine file's page.

A report's data model (:mod:`.model`) and a study's claim rows (:mod:`.claims`) are what the pages are made of.
"""
