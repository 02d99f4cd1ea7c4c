"""What MuJoCo Warp and MJX accept, known without either installed: their lint checks (RA801-RA803 in
:mod:`.warp_checks`, RA811-RA815 in :mod:`.mjx_checks`, what both share in :mod:`.engines`) and
``build --target mjwarp``'s check against MuJoCo Warp's own ``put_model`` (:mod:`.put_model_check`).
Batches of worlds on MuJoCo Warp itself are :mod:`assembler.warp`, which needs it installed."""
