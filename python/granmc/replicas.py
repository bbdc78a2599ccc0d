"""Statistics over independent replicas, as granmc computes them (kernel/analysis/replica_statistics.hpp).

The mean over the N replicas and the confidence half-width lambda_p sqrt(Var / N) of 001 eq. (31), with the
empirical variance eta_2 - eta_1^2 (001 after eq. 32: divided by N, numpy's ddof=0) and lambda_p = 3.2 (confidence
level p = 0.999, 001 sec. 5.1). An interval a script prints is then the interval of the HDF5 file's `ci` records.
"""
import numpy as np

LAMBDA_P = 3.2  # 001 sec. 5.1; kernel/analysis/replica_statistics.hpp, confidence_lambda_p


def mean_ci(values, axis=0):
    """The mean over replicas along `axis` and its confidence half-width lambda_p sqrt(Var / N).

    Floats for one-dimensional input, arrays otherwise. Values that are not finite are not dropped: a replica
    that failed makes the interval nan, as it should.
    """
    v = np.asarray(values, dtype=float)
    n = v.shape[axis]
    if n == 0:
        raise ValueError("mean_ci: no replicas")
    mean = v.mean(axis=axis)
    ci = LAMBDA_P * v.std(axis=axis, ddof=0) / np.sqrt(n)
    if np.ndim(mean) == 0:
        return float(mean), float(ci)
    return mean, ci
