"""The source paper's reproduction: study stages, claims, the paper's numbers and captions."""
