"""Drop campaigns: Monte Carlo and sensitivity over uncertain drop conditions.

A campaign file (:mod:`~auxbearing.campaign.config`) names a machine and its uncertain inputs; a
design (:mod:`~auxbearing.campaign.sampling`) turns a seed into samples; each sample is run into a
flat record (:mod:`~auxbearing.campaign.evaluate`) on Dask workers (:mod:`~auxbearing.campaign.run`)
and streamed into a Zarr store (:mod:`~auxbearing.campaign.store`) that a second call resumes;
:mod:`~auxbearing.campaign.statistics` and :mod:`~auxbearing.report.campaign` turn the store into
probabilities, quantiles, sensitivity indices and figures.
"""

from auxbearing.campaign.config import Campaign, CampaignInput, apply_sample, campaign_from_mapping, read_campaign

__all__ = ["Campaign", "CampaignInput", "apply_sample", "campaign_from_mapping", "read_campaign"]
