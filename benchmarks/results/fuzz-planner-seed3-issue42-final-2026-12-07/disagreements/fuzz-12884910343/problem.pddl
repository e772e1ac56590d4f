(define (problem fuzz-12884910343-1) (:domain fuzz-12884910343)
  (:init (at 1.75 (f2)) (at 2.25 (not (f2))) (f2) (at 2.5 (not (f2))) (= (x0) 1) (= (x1) 1) (= (x2) 2) (at 0.5 (f2)) (at 0.5015 (not (f2))) (f3) (g0 o1) (g0 o2))
  (:goal (and (f1) (>= (x0) 2)))
  (:metric minimize (total-time)))
